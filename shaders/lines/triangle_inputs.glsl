// The triangle a per-triangle line pass cuts, as its geometry stage or
// compute pass (triangles_comp.glsl) fills it in: the corners in clip
// coordinates and their vertex indices. The family's own per-vertex
// quantities are in its array tri[3].
vec4 tri_clip[3];
int tri_id[3];
