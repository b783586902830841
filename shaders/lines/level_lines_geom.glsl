// level_lines.glsl in the geometry stage.
layout(triangles) in;
layout(triangle_strip, max_vertices = 64) out;

in LevelVertexBlock {
    LevelVertex v;
} v_in[];

void main() {
    for (int i = 0; i < 3; ++i) {
        tri[i] = v_in[i].v;
        tri_clip[i] = gl_in[i].gl_Position;
    }
    extract_level_lines();
}
