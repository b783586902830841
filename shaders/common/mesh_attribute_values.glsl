// The names of mesh_attributes.glsl as plain values, for the stages that
// have no vertex attributes: a compute pass fills them per vertex
// (mesh_vertex_fetch.glsl); in a geometry stage they only let the family's
// per-vertex functions (lines/*_vertex.glsl) compile beside its structures.
vec3 a_position, a_normal, a_d1, a_d2, a_fine_normal;
vec2 a_curv;
vec4 a_dcurv;
float a_unreliable;
