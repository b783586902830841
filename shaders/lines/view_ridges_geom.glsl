// view_ridges.glsl in the geometry stage.
layout(triangles) in;
layout(triangle_strip, max_vertices = 16) out;  // three half segments of an apparent ridge, a highlight

in ViewRidgeVertexBlock {
    ViewRidgeVertex v;
} v_in[];

void main() {
    for (int i = 0; i < 3; ++i) {
        tri[i] = v_in[i].v;
        tri_clip[i] = gl_in[i].gl_Position;
    }
    extract_view_ridges();
}
