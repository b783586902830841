// Creases (the geometry stage, crease_geom.glsl, or a compute pass,
// creases_comp.glsl): a sharp edge is drawn
//   - as a crease line when it is turned towards the viewer (one of its two
//     faces faces the eye) and creases are on;
//   - as occluding contour when one face faces the eye and the other away:
//     there the contour runs along the edge, and the n.v zero crossings
//     inside the faces (isolines.glsl) would leave a gap.
// Hidden parts are removed by the same depth test as every line.
float edge_facing_a[2], edge_facing_b[2];  // n . v of each face at each end

uniform int u_creases;
uniform int u_contours;
uniform int u_hidden_lines;  // every crease is then drawn: the fragment stage dashes the hidden ones
uniform int u_silhouette_only;  // contours only where they border the background

void extract_crease() {
    bool front_a = edge_facing_a[0] > 0.0 || edge_facing_a[1] > 0.0;
    bool front_b = edge_facing_b[0] > 0.0 || edge_facing_b[1] > 0.0;
    bool visible = front_a || front_b || u_hidden_lines != 0;
    bool silhouette = front_a != front_b;
    if (!((u_creases != 0 && visible) || (u_contours != 0 && silhouette))) return;
    float tolerance = 0.5 * distance(edge_position[0], edge_position[1]);
    // A silhouette crease drawn as contour only: exterior only when asked.
    exterior_only_ = !(u_creases != 0 && visible) && u_silhouette_only != 0 ? 1.0 : 0.0;
    emit_segment(edge_clip[0], edge_clip[1], 1.0, 1.0, tolerance);
}
