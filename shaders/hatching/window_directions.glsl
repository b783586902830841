// The principal directions as the hatching sees them, per vertex: projected
// into the window, and how well they are defined (render/hatching/hatch_field.h,
// shader_hatching.glsl).
uniform vec2 u_viewport;        // pixels
uniform float u_feature_size;   // fs: |k1 - k2| fs = 1 is a clearly defined direction

// A model-space direction d at the point with clip coordinates `clip` (mvp:
// model -> clip), in window pixels per unit.
vec2 window_direction(mat4 mvp, vec4 clip, vec3 d) {
    vec4 dc = mvp * vec4(d, 0.0);
    return clip.w > 0.0 ? (dc.xy - clip.xy * (dc.w / clip.w)) / clip.w * (0.5 * u_viewport) : vec2(0.0);
}

// In [0, 1]: 0 at umbilics, flat areas and unreliable vertices.
float direction_reliability() {
    return a_unreliable > 0.0 ? 0.0 : clamp(abs(a_curv.x - a_curv.y) * u_feature_size, 0.0, 1.0);
}

// (cos 2a, sin 2a) of a window direction at angle a: the same for d and -d, so
// it can be interpolated across a triangle whose vertices' signs disagree.
vec2 doubled_angle(vec2 d) {
    float l2 = dot(d, d);
    return l2 > 1e-24 ? vec2(d.x * d.x - d.y * d.y, 2.0 * d.x * d.y) / l2 : vec2(0.0);
}
