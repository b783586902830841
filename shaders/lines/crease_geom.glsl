// Creases, geometry stage (crease_lines.glsl): one sharp edge (GL_LINES).
layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;

in CreaseVertex {
    vec3 position;
    float facing_a, facing_b;
} v_in[];

void main() {
    for (int i = 0; i < 2; ++i) {
        edge_position[i] = v_in[i].position;
        edge_clip[i] = gl_in[i].gl_Position;
        edge_facing_a[i] = v_in[i].facing_a;
        edge_facing_b[i] = v_in[i].facing_b;
    }
    extract_crease();
}
