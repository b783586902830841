// How every line pass hands over a segment, whatever makes it: the geometry
// stage emits it as a quad (line_quad.glsl), a compute pass appends it to the
// segment buffer (segment_append.glsl); each defines emit_window_segment.
uniform vec2 u_viewport;     // pixels
uniform float u_line_width;  // pixels

float exterior_only_ = 0.0;  // set by a pass before it emits exterior-silhouette segments

// A segment between two points in window coordinates (pixels, depth).
void emit_window_segment(vec3 p0, vec3 p1, float alpha0, float alpha1, float tolerance, float width,
                         bool on_surface);

vec3 to_window(vec4 clip) {
    vec3 ndc = clip.xyz / clip.w;
    return vec3((ndc.xy * 0.5 + 0.5) * u_viewport, ndc.z * 0.5 + 0.5);
}

// A line of the line width between two points in clip coordinates.
void emit_segment(vec4 clip0, vec4 clip1, float alpha0, float alpha1, float tolerance) {
    if (clip0.w <= 0.0 || clip1.w <= 0.0) return;  // behind the eye
    emit_window_segment(to_window(clip0), to_window(clip1), alpha0, alpha1, tolerance, u_line_width, false);
}
