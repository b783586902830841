// Surface pass, vertex stage.
uniform mat4 u_mvp;
uniform mat4 u_model_view;
uniform mat3 u_normal_matrix;  // model -> camera for normals
uniform vec2 u_viewport;       // pixels
uniform int u_colormap;

out vec3 v_normal;       // camera coordinates
out vec2 v_map_value;    // colormap_value()
out vec4 v_hatch_dirs;   // screen directions of d1 (xy) and d2 (zw) as doubled-angle vectors

// Direction in window pixels of the tangent d at the point with clip
// coordinates `clip` (derivative of the perspective division), encoded as
// (cos 2a, sin 2a): principal directions are defined up to sign, and this
// encoding interpolates across vertices whose d1 point opposite ways.
vec2 doubled_angle(vec4 clip, vec3 d) {
    vec4 dc = u_mvp * vec4(d, 0.0);
    vec2 s = (dc.xy - clip.xy * (dc.w / clip.w)) / clip.w * u_viewport;
    float len2 = dot(s, s);
    if (len2 < 1e-20) return vec2(0.0);
    return vec2(s.x * s.x - s.y * s.y, 2.0 * s.x * s.y) / len2;
}

void main() {
    vec4 clip = u_mvp * vec4(a_position, 1.0);
    v_normal = u_normal_matrix * a_normal;
    v_map_value = colormap_value(u_colormap, a_curv, a_dcurv);
    v_hatch_dirs = vec4(doubled_angle(clip, a_d1), doubled_angle(clip, a_d2));
    gl_Position = clip;
}
