// Mesh boundaries, geometry stage: each boundary edge (GL_LINES from
// render/fields/mesh_buffers.cpp) becomes a screen-space quad.
layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;

in LineVertexBlock {
    LineVertex v;
    flat int id;
} v_in[];

void main() {
    float tolerance = 0.5 * distance(v_in[0].v.position, v_in[1].v.position);
    emit_segment(gl_in[0].gl_Position, gl_in[1].gl_Position, 1.0, 1.0, tolerance);
}
