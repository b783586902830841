// Crease pass, geometry stage: a sharp edge is drawn
//   - as a crease line when it is turned towards the viewer (one of its two
//     faces faces the eye) and creases are on;
//   - as occluding contour when one face faces the eye and the other away:
//     there the contour runs along the edge, and the n.v zero crossings
//     inside the faces (isolines_geom.glsl) would leave a gap.
// Hidden parts are removed by the same depth test as every line.
layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;

in CreaseVertex {
    vec3 position;
    float facing_a, facing_b;
} v_in[];

uniform int u_creases;
uniform int u_contours;
uniform int u_hidden_lines;  // every crease is then drawn: the fragment stage dashes the hidden ones
uniform int u_silhouette_only;  // contours only where they border the background

void main() {
    bool front_a = v_in[0].facing_a > 0.0 || v_in[1].facing_a > 0.0;
    bool front_b = v_in[0].facing_b > 0.0 || v_in[1].facing_b > 0.0;
    bool visible = front_a || front_b || u_hidden_lines != 0;
    bool silhouette = front_a != front_b;
    if (!((u_creases != 0 && visible) || (u_contours != 0 && silhouette))) return;
    float tolerance = 0.5 * distance(v_in[0].position, v_in[1].position);
    // A silhouette crease drawn as contour only: exterior only when asked.
    exterior_only_ = !(u_creases != 0 && visible) && u_silhouette_only != 0 ? 1.0 : 0.0;
    emit_segment(gl_in[0].gl_Position, gl_in[1].gl_Position, 1.0, 1.0, tolerance);
}
