// Mesh boundaries, geometry stage (boundary_lines.glsl): each boundary edge
// (GL_LINES from render/fields/mesh_buffers.cpp) becomes a screen-space quad.
layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;

in LineVertexBlock {
    LineVertex v;
    flat int id;
} v_in[];

void main() {
    for (int i = 0; i < 2; ++i) {
        edge_position[i] = v_in[i].v.position;
        edge_clip[i] = gl_in[i].gl_Position;
    }
    extract_boundary();
}
