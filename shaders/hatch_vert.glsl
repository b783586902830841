// Hatching strokes, vertex stage: what hatch_geom.glsl needs per vertex.
uniform mat4 u_mvp;

out HatchVertex {
    vec3 position;  // model coordinates
    vec3 normal;
    vec3 d1, d2;
} v_out;

void main() {
    v_out.position = a_position;
    v_out.normal = a_normal;
    v_out.d1 = a_d1;
    v_out.d2 = a_d2;
    gl_Position = u_mvp * vec4(a_position, 1.0);
}
