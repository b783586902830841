// Surface pass, vertex stage.
uniform mat4 u_mvp;
uniform mat4 u_model_view;
uniform mat3 u_normal_matrix;  // model -> camera for normals
uniform int u_colormap;

out vec3 v_normal;       // camera coordinates
out vec2 v_map_value;    // colormap_value()
#ifdef KAPPA_HATCHING
out vec4 v_hatch_dirs;   // doubled window angles of d1, d2 times their reliability (window_directions.glsl)
#endif

void main() {
    vec4 clip = u_mvp * vec4(a_position, 1.0);
    v_normal = u_normal_matrix * a_fine_normal;
    v_map_value = colormap_value(u_colormap, a_curv, a_dcurv);
    gl_Position = clip;
#ifdef KAPPA_HATCHING
    float reliability = direction_reliability();
    v_hatch_dirs = vec4(doubled_angle(window_direction(u_mvp, clip, a_d1)),
                        doubled_angle(window_direction(u_mvp, clip, a_d2))) * reliability;
#endif
}
