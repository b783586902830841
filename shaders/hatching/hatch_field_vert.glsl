// Hatching field pass, vertex stage: per vertex, both principal directions
// projected to the window (pixels per unit of surface length), how well they
// are defined, and the tone (render/hatching/hatch_field.h).
// (window_direction, direction_reliability: window_directions.glsl.)
uniform mat4 u_mvp;
uniform vec3 u_eye;             // model coordinates
uniform mat3 u_normal_matrix;   // model -> camera, for the light
uniform vec3 u_light;           // towards the light, camera coordinates, unit

out HatchVertex {
    vec2 direction1;    // d1, window pixels per unit
    vec2 direction2;    // d2
    float reliability;  // in [0, 1]: 0 at umbilics, flat areas and unreliable vertices
    float darkness;     // in [0, 1]: how dark the tone is (as the shading's light)
    float facing;       // n.v with the shading normal
} v_out;

void main() {
    vec4 clip = u_mvp * vec4(a_position, 1.0);
    gl_Position = clip;
    v_out.direction1 = window_direction(u_mvp, clip, a_d1);
    v_out.direction2 = window_direction(u_mvp, clip, a_d2);
    v_out.reliability = direction_reliability();
    float tone = max(dot(normalize(u_normal_matrix * a_fine_normal), u_light), 0.0);
    v_out.darkness = clamp((0.95 - tone) / 0.8, 0.0, 1.0);
    v_out.facing = dot(a_fine_normal, normalize(u_eye - a_position));
}
