// Line passes, fragment stage: anti-aliased coverage of a segment of
// constant width, hidden where the surface occludes its centre line.
// Output goes to a one-channel coverage buffer blended with GL_MAX, so
// overlapping caps at joints and crossing lines never darken twice.
in LineFragment {
    flat vec4 segment;
    flat vec2 depth;
    flat vec2 alpha;
    flat float tolerance;
    flat float width;
    flat float on_surface;
    flat float exterior_only;
} f_in;

uniform sampler2D u_depth;    // surface depth (window depth, single-sampled)
uniform vec2 u_depth_params;  // (P[2][2], P[3][2]) of the projection: window depth -> camera distance
uniform int u_hidden_lines;   // 1: hidden parts are drawn dashed and light instead of not at all

out float o_coverage;

float camera_distance(float window_depth) {
    return u_depth_params.y / (window_depth * 2.0 - 1.0 + u_depth_params.x);
}

void main() {
    vec2 p = gl_FragCoord.xy;
    vec2 a = f_in.segment.xy, ab = f_in.segment.zw - a;
    float len2 = dot(ab, ab);
    float t = len2 > 1e-12 ? clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    vec2 q = a + t * ab;  // closest point of the centre line
    // Box-filtered coverage of a line of width w at distance d from its centre.
    float coverage = clamp(0.5 * f_in.width + 0.5 - distance(p, q), 0.0, 1.0);
    if (coverage <= 0.0) discard;

    // Visibility is decided at q, not at p, so a visible line keeps its full
    // width even where the surface beside it is nearer (at contours). The
    // farthest surface depth in the 3x3 pixels around q absorbs the surface
    // slope within a pixel; `tolerance` the gap between the smooth curve and
    // the polygons.
    // The pixel at q alone decides most fragments: the 3x3 maximum is never
    // nearer, so a line visible against it is visible against the maximum.
    if (f_in.on_surface > 0.0 && texelFetch(u_depth, ivec2(p), 0).r == 1.0) discard;
    ivec2 size = textureSize(u_depth, 0);
    if (f_in.exterior_only > 0.0) {
        // The exterior silhouette: background on one side of the line, a line-width and
        // two pixels away from its centre.
        vec2 side = len2 > 1e-12 ? normalize(vec2(-ab.y, ab.x)) : vec2(1.0, 0.0);
        float reach = 0.5 * f_in.width + 2.0;
        ivec2 a_side = clamp(ivec2(floor(q + side * reach)), ivec2(0), size - 1);
        ivec2 b_side = clamp(ivec2(floor(q - side * reach)), ivec2(0), size - 1);
        if (texelFetch(u_depth, a_side, 0).r < 1.0 && texelFetch(u_depth, b_side, 0).r < 1.0) discard;
    }
    ivec2 qi = clamp(ivec2(floor(q)), ivec2(0), size - 1);
    float line_distance = camera_distance(mix(f_in.depth.x, f_in.depth.y, t));
    float centre = texelFetch(u_depth, qi, 0).r;
    float shade = 1.0;
    if (centre < 1.0 && line_distance > camera_distance(centre) + f_in.tolerance) {
        float farthest = centre;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx)
                farthest = max(farthest, texelFetch(u_depth, clamp(qi + ivec2(dx, dy), ivec2(0), size - 1), 0).r);
        if (farthest < 1.0 && line_distance > camera_distance(farthest) + f_in.tolerance) {
            // Hidden: not drawn, or (--hidden-lines on) dashes of 6 px every 10 px at 35% ink,
            // the dashes measured along the segment from its first end.
            if (u_hidden_lines == 0 || f_in.on_surface > 0.0 || mod(t * sqrt(len2), 10.0) > 6.0) discard;
            shade = 0.35;
        }
    }
    o_coverage = shade * coverage * mix(f_in.alpha.x, f_in.alpha.y, t);
}
