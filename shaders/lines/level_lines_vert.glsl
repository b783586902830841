// Level lines, vertex stage: the value whose levels are drawn
// (level_lines_geom.glsl): n.l for isophotes, height along y for topo.
uniform mat4 u_mvp;
uniform int u_kind;          // 0: isophotes, 1: topo
uniform vec3 u_light_model;  // unit, towards the light, model coordinates
uniform vec3 u_eye;          // model coordinates

out LevelVertex {
    vec3 position;
    float value;
    float facing;  // n.(eye - position): > 0 where turned towards the eye
} v_out;

void main() {
    v_out.position = a_position;
    v_out.value = u_kind == 0 ? dot(a_normal, u_light_model) : a_position.y;
    v_out.facing = dot(a_normal, u_eye - a_position);
    gl_Position = u_mvp * vec4(a_position, 1.0);
}
