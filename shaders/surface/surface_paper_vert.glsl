// Surface pass on white paper (no shading, no colour map), vertex stage:
// the position alone. With nothing to interpolate, a software rasteriser
// sets up each triangle for its depth only.
layout(location = 0) in vec3 a_position;

uniform mat4 u_mvp;

void main() { gl_Position = u_mvp * vec4(a_position, 1.0); }
