// The geometry stage's emit_window_segment (segment_emit.glsl): a segment
// becomes a screen-space quad of the line width plus half a pixel of
// anti-aliasing margin, extended by the same amount past both ends (round
// caps, so consecutive segments join without gaps). lines_frag.glsl computes
// the exact coverage.
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
out LineFragment {
    flat vec4 segment;   // end points in window pixels (x0, y0, x1, y1)
    flat vec2 depth;     // window depth [0, 1] at the end points
    flat vec2 alpha;     // opacity at the end points (fading)
    flat float tolerance;  // occlusion tolerance, camera units
    flat float width;      // pixels
    flat float on_surface; // 1: drawn only over the surface (hatching strokes never overhang the silhouette)
    flat float exterior_only; // 1: drawn only where one side is background (the exterior silhouette)
} g_out;

// Outputs are undefined after EmitVertex: every corner writes them again.
vec4 segment_; vec2 depth_, alpha_; float tolerance_, width_, on_surface_;

void emit_corner(vec2 window_xy, float window_z) {
    g_out.segment = segment_;
    g_out.depth = depth_;
    g_out.alpha = alpha_;
    g_out.tolerance = tolerance_;
    g_out.width = width_;
    g_out.on_surface = on_surface_;
    g_out.exterior_only = exterior_only_;
    gl_Position = vec4(window_xy / u_viewport * 2.0 - 1.0, window_z * 2.0 - 1.0, 1.0);
    EmitVertex();
}

// A segment between two points in window coordinates (pixels, depth).
void emit_window_segment(vec3 p0, vec3 p1, float alpha0, float alpha1, float tolerance, float width,
                         bool on_surface) {
    if (max(alpha0, alpha1) <= 0.0) return;
    vec2 dir = p1.xy - p0.xy;
    float len = length(dir);
    dir = len > 1e-6 ? dir / len : vec2(1.0, 0.0);
    vec2 nrm = vec2(-dir.y, dir.x);
    float r = 0.5 * width + 0.5;  // lines_frag.glsl gives no coverage farther from the centre line
    segment_ = vec4(p0.xy, p1.xy);
    depth_ = vec2(p0.z, p1.z);
    alpha_ = vec2(alpha0, alpha1);
    tolerance_ = tolerance;
    width_ = width;
    on_surface_ = on_surface ? 1.0 : 0.0;
    float z = min(p0.z, p1.z);  // any depth inside the range: depth testing is done in lines_frag
    emit_corner(p0.xy + (-dir - nrm) * r, z);
    emit_corner(p0.xy + (-dir + nrm) * r, z);
    emit_corner(p1.xy + (dir - nrm) * r, z);
    emit_corner(p1.xy + (dir + nrm) * r, z);
    EndPrimitive();
}
