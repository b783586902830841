// Shader hatching's field pass, vertex stage (render/hatching/shader_hatching.h):
// per vertex, both principal directions projected into the window as
// doubled angles (window_directions.glsl: sign-free, so they interpolate
// across a triangle whose vertices' signs disagree) times their
// reliability, and the tone, as the streamlines' field has it
// (hatch_field_vert.glsl).
uniform mat4 u_mvp;
uniform vec3 u_eye;            // model coordinates
uniform mat3 u_normal_matrix;  // model -> camera, for the light
uniform vec3 u_light;          // towards the light, camera coordinates, unit

out HatchVectors {
    vec4 directions;  // (cos 2a1, sin 2a1, cos 2a2, sin 2a2) times the reliability
    float darkness;   // in [0, 1]
    float facing;     // n.v with the shading normal
} v_out;

void main() {
    vec4 clip = u_mvp * vec4(a_position, 1.0);
    gl_Position = clip;
    v_out.directions = vec4(doubled_angle(window_direction(u_mvp, clip, a_d1)),
                            doubled_angle(window_direction(u_mvp, clip, a_d2))) * direction_reliability();
    float tone = max(dot(normalize(u_normal_matrix * a_fine_normal), u_light), 0.0);
    v_out.darkness = clamp((0.95 - tone) / 0.8, 0.0, 1.0);
    v_out.facing = dot(a_fine_normal, normalize(u_eye - a_position));
}
