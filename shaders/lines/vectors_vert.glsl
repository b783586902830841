// Vector glyphs, vertex stage: one vertex in every u_stride of the mesh.
uniform mat4 u_mvp;
uniform vec3 u_eye;  // model coordinates
uniform int u_stride;

out GlyphVertex {
    vec3 position, normal, d1, d2, view;
    vec2 curv;
    float keep;
} v_out;

void main() {
    v_out.position = a_position;
    v_out.normal = a_normal;
    v_out.d1 = a_d1;
    v_out.d2 = a_d2;
    v_out.view = normalize(u_eye - a_position);
    v_out.curv = a_curv;
    v_out.keep = (gl_VertexID % u_stride == 0 && a_unreliable == 0.0) ? 1.0 : 0.0;
    gl_Position = u_mvp * vec4(a_position, 1.0);
}
