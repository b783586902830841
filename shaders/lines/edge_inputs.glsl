// The edge a per-edge line pass (boundaries, creases) draws, as its geometry
// stage or compute pass fills it in: its end points in model and clip
// coordinates.
vec3 edge_position[2];
vec4 edge_clip[2];
