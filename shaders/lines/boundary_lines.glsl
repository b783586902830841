// Mesh boundaries: each open boundary edge is a segment (the geometry stage,
// boundary_geom.glsl, or a compute pass, boundaries_comp.glsl).
void extract_boundary() {
    float tolerance = 0.5 * distance(edge_position[0], edge_position[1]);
    emit_segment(edge_clip[0], edge_clip[1], 1.0, 1.0, tolerance);
}
