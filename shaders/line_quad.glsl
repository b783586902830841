// Shared by the line geometry shaders: a 3D segment becomes a screen-space
// quad of the line width plus one pixel of anti-aliasing margin, extended
// by the same amount past both ends (round caps, so consecutive segments
// join without gaps). lines_frag.glsl computes the exact coverage.
//
// Why geometry and not a fragment-shader zero test: a per-fragment test
// |f| < w * fwidth(f) gives lines whose width follows the gradient of f (thin
// where n.v changes fast, i.e. exactly at contours; wide and blotchy where
// kr is flat), only half a line at silhouettes (the other half has no
// surface to be drawn on) and dashes on coarse meshes. Segments cut per
// triangle from the linearly interpolated field, expanded here, have a
// constant width in pixels at any zoom, are continuous across triangles
// (shared edges are cut at bit-identical points) and can be tested for
// visibility along their centre line.
uniform vec2 u_viewport;     // pixels
uniform float u_line_width;  // pixels

out LineFragment {
    flat vec4 segment;   // end points in window pixels (x0, y0, x1, y1)
    flat vec2 depth;     // window depth [0, 1] at the end points
    flat vec2 alpha;     // opacity at the end points (fading)
    flat float tolerance;  // occlusion tolerance, camera units
} g_out;

vec3 to_window(vec4 clip) {
    vec3 ndc = clip.xyz / clip.w;
    return vec3((ndc.xy * 0.5 + 0.5) * u_viewport, ndc.z * 0.5 + 0.5);
}

// Outputs are undefined after EmitVertex: every corner writes them again.
vec4 segment_; vec2 depth_, alpha_; float tolerance_;

void emit_corner(vec2 window_xy, float window_z) {
    g_out.segment = segment_;
    g_out.depth = depth_;
    g_out.alpha = alpha_;
    g_out.tolerance = tolerance_;
    gl_Position = vec4(window_xy / u_viewport * 2.0 - 1.0, window_z * 2.0 - 1.0, 1.0);
    EmitVertex();
}

void emit_segment(vec4 clip0, vec4 clip1, float alpha0, float alpha1, float tolerance) {
    if (clip0.w <= 0.0 || clip1.w <= 0.0) return;  // behind the eye
    if (max(alpha0, alpha1) <= 0.0) return;
    vec3 p0 = to_window(clip0), p1 = to_window(clip1);
    vec2 dir = p1.xy - p0.xy;
    float len = length(dir);
    dir = len > 1e-6 ? dir / len : vec2(1.0, 0.0);
    vec2 nrm = vec2(-dir.y, dir.x);
    float r = 0.5 * u_line_width + 1.0;
    segment_ = vec4(p0.xy, p1.xy);
    depth_ = vec2(p0.z, p1.z);
    alpha_ = vec2(alpha0, alpha1);
    tolerance_ = tolerance;
    float z = min(p0.z, p1.z);  // any depth inside the range: depth testing is done in lines_frag
    emit_corner(p0.xy + (-dir - nrm) * r, z);
    emit_corner(p0.xy + (-dir + nrm) * r, z);
    emit_corner(p1.xy + (dir - nrm) * r, z);
    emit_corner(p1.xy + (dir + nrm) * r, z);
    EndPrimitive();
}
