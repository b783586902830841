// Occluding and suggestive contours, geometry stage (isolines.glsl).
layout(triangles) in;
#ifdef KAPPA_HIGHLIGHTS
layout(triangle_strip, max_vertices = 16) out;  // contour, suggestive contour, highlight, dwkr
#else
layout(triangle_strip, max_vertices = 8) out;  // contour, suggestive contour (fewer outputs: faster on llvmpipe)
#endif

in LineVertexBlock {
    LineVertex v;
    flat int id;
} v_in[];

void main() {
    for (int i = 0; i < 3; ++i) {
        tri[i] = v_in[i].v;
        tri_id[i] = v_in[i].id;
        tri_clip[i] = gl_in[i].gl_Position;
    }
    extract_isolines();
}
