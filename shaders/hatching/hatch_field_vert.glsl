// Hatching field pass, vertex stage: per vertex, both principal directions
// projected to the window (pixels per unit of surface length), how well they
// are defined, and the tone (render/hatching/hatch_field.h).
uniform mat4 u_mvp;
uniform vec3 u_eye;             // model coordinates
uniform mat3 u_normal_matrix;   // model -> camera, for the light
uniform vec3 u_light;           // towards the light, camera coordinates, unit
uniform vec2 u_viewport;        // pixels
uniform float u_feature_size;   // fs: |k1 - k2| fs = 1 is a clearly defined direction

out HatchVertex {
    vec2 direction1;    // d1, window pixels per unit
    vec2 direction2;    // d2
    float reliability;  // in [0, 1]: 0 at umbilics, flat areas and unreliable vertices
    float darkness;     // in [0, 1]: how dark the tone is (as the shading's light)
    float facing;       // n.v with the shading normal
} v_out;

vec2 window_direction(vec4 clip, vec3 d) {
    vec4 dc = u_mvp * vec4(d, 0.0);
    return clip.w > 0.0 ? (dc.xy - clip.xy * (dc.w / clip.w)) / clip.w * (0.5 * u_viewport) : vec2(0.0);
}

void main() {
    vec4 clip = u_mvp * vec4(a_position, 1.0);
    gl_Position = clip;
    v_out.direction1 = window_direction(clip, a_d1);
    v_out.direction2 = window_direction(clip, a_d2);
    v_out.reliability = a_unreliable > 0.0 ? 0.0 : clamp(abs(a_curv.x - a_curv.y) * u_feature_size, 0.0, 1.0);
    float tone = max(dot(normalize(u_normal_matrix * a_fine_normal), u_light), 0.0);
    v_out.darkness = clamp((0.95 - tone) / 0.8, 0.0, 1.0);
    v_out.facing = dot(a_fine_normal, normalize(u_eye - a_position));
}
