// Line passes, vertex stage: per-vertex view-dependent quantities for the
// geometry shader that extracts zero crossings (isolines_geom.glsl).
uniform mat4 u_mvp;
uniform vec3 u_eye;               // model coordinates
uniform float u_feature_size_sq;  // fs^2: Dw kr * fs^2 is dimensionless
uniform mat3 u_normal_matrix;     // model -> camera, for the light
uniform vec3 u_light;             // towards the light, camera coordinates, unit
uniform vec2 u_viewport;          // pixels
uniform int u_hatching;           // 0: no hatching strokes

out LineVertex {
    vec3 position;      // model coordinates
    float ndotv;
    float kr;           // kr sin^2(theta)
    float sc_strength;  // Dw kr * fs^2, compared with the dimensionless threshold
    float unreliable;
    flat int id;        // vertex index: fixes the order in which shared edges are cut
    vec4 hatch_dirs;    // window-space directions of d1 (xy) and d2 (zw), unit, up to sign
    float tone;         // Lambertian n.l, for the hatching density
} v_out;

// Window-space direction of the tangent d at the point with clip coordinates
// `clip` (derivative of the perspective division), unit or zero.
vec2 screen_direction(vec4 clip, vec3 d) {
    vec4 dc = u_mvp * vec4(d, 0.0);
    vec2 s = (dc.xy - clip.xy * (dc.w / clip.w)) / clip.w * u_viewport;
    float len = length(s);
    return len > 1e-6 ? s / len : vec2(0.0);
}

void main() {
    vec3 v = normalize(u_eye - a_position);
    ViewQuantities q = view_quantities(a_normal, a_d1, a_d2, a_curv, a_dcurv, v);
    v_out.position = a_position;
    v_out.ndotv = q.ndotv;
    v_out.kr = q.kr_sin2;
    v_out.sc_strength = q.dwkr * u_feature_size_sq;
    v_out.unreliable = a_unreliable;
    v_out.id = gl_VertexID;
    vec4 clip = u_mvp * vec4(a_position, 1.0);
    v_out.hatch_dirs = vec4(0.0);
    v_out.tone = 1.0;
    if (u_hatching != 0) {
        v_out.hatch_dirs = vec4(screen_direction(clip, a_d1), screen_direction(clip, a_d2));
        v_out.tone = max(dot(normalize(u_normal_matrix * a_normal), u_light), 0.0);
    }
    gl_Position = clip;
}
