// Surface pass without a colour map, vertex stage: only the position and the
// pixel-scale normal are read, so a software rasteriser fetches and shades
// less per vertex (surface_vert.glsl reads the curvature fields too).
layout(location = 0) in vec3 a_position;
layout(location = 7) in vec3 a_fine_normal;

uniform mat4 u_mvp;
uniform mat3 u_normal_matrix;  // model -> camera for normals

out vec3 v_normal;     // camera coordinates
out vec2 v_map_value;  // unused without a colour map

void main() {
    v_normal = u_normal_matrix * a_fine_normal;
    v_map_value = vec2(0.0);
    gl_Position = u_mvp * vec4(a_position, 1.0);
}
