// Mesh boundaries, geometry stage: each boundary edge (GL_LINES from
// render/fields/mesh_buffers.cpp) becomes a screen-space quad.
layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;

in LineVertex {
    vec3 position;
    float ndotv;
    float contour_ndotv;
    float kr;
    float sc_strength;
    float unreliable;
    flat int id;
} v_in[];

void main() {
    float tolerance = 0.5 * distance(v_in[0].position, v_in[1].position);
    emit_segment(gl_in[0].gl_Position, gl_in[1].gl_Position, 1.0, 1.0, tolerance);
}
