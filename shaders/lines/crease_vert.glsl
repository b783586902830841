// Crease pass, vertex stage: a sharp edge's end point with the normals of
// the two faces along the edge (render/fields/mesh_buffers.cpp, geometry/creases.h).
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal_a;
layout(location = 2) in vec3 a_normal_b;
uniform mat4 u_mvp;
uniform vec3 u_eye;  // model coordinates

out CreaseVertex {
    vec3 position;
    float facing_a, facing_b;  // n . v of each face at this end
} v_out;

void main() {
    vec3 v = u_eye - a_position;
    v_out.position = a_position;
    v_out.facing_a = dot(a_normal_a, v);
    v_out.facing_b = dot(a_normal_b, v);
    gl_Position = u_mvp * vec4(a_position, 1.0);
}
