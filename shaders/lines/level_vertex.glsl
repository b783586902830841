// Level lines, per vertex (the vertex stage, level_lines_vert.glsl, or a
// compute pass, triangles_comp.glsl): the value whose levels are drawn
// (level_lines_geom.glsl): n.l for isophotes, height along y for topo.
uniform mat4 u_mvp;
uniform int u_kind;          // 0: isophotes, 1: topo
uniform vec3 u_light_model;  // unit, towards the light, model coordinates
uniform vec3 u_eye;          // model coordinates

struct LevelVertex {
    vec3 position;
    float value;
    float facing;  // n.(eye - position): > 0 where turned towards the eye
};

LevelVertex level_vertex() {
    LevelVertex o;
    o.position = a_position;
    o.value = u_kind == 0 ? dot(a_normal, u_light_model) : a_position.y;
    o.facing = dot(a_normal, u_eye - a_position);
    return o;
}
