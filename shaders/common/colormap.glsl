// Curvature colour maps (Rusinkiewicz 2004, figure 4). Shared by the
// surface and the colour bar. Map ids follow render::ColorMap:
// 1 k1, 2 k2, 3 mean, 4 Gaussian, 5 principal, 6 |C|.
// `range` is the robust range from render/surface/colormap.cpp: signed maps are
// symmetric, [-range, range]; |C| is [0, range].

const vec3 kWhite = vec3(1.0);
const vec3 kNegative = vec3(0.19, 0.34, 0.80);  // blue
const vec3 kPositive = vec3(0.80, 0.14, 0.12);  // red

// Diverging blue - white - red for a signed value scaled to [-1, 1].
vec3 diverging(float x) {
    x = clamp(x, -1.0, 1.0);
    return x < 0.0 ? mix(kWhite, kNegative, -x) : mix(kWhite, kPositive, x);
}

// Sequential white - orange - dark purple for x in [0, 1].
vec3 sequential(float x) {
    x = clamp(x, 0.0, 1.0);
    vec3 mid = vec3(0.98, 0.60, 0.18), dark = vec3(0.38, 0.04, 0.36);
    return x < 0.5 ? mix(kWhite, mid, 2.0 * x) : mix(mid, dark, 2.0 * x - 1.0);
}

// Both principal curvatures at a glance: the hue says which signs they have
// (blue: both positive, convex; red: both negative, concave; green: opposite
// signs, saddle), the saturation how large the larger one is.
vec3 principal_colors(float k1, float k2, float range) {
    float s1 = clamp(k1 / range, -1.0, 1.0), s2 = clamp(k2 / range, -1.0, 1.0);
    float convex = smoothstep(0.0, 0.15, s2);    // k2 > 0, hence k1 > 0
    float concave = smoothstep(0.0, 0.15, -s1);  // k1 < 0, hence k2 < 0
    float saddle = (1.0 - convex) * (1.0 - concave);
    vec3 hue = convex * vec3(0.15, 0.38, 0.95) + concave * vec3(0.92, 0.22, 0.14) + saddle * vec3(0.16, 0.68, 0.24);
    return mix(kWhite, hue, max(abs(s1), abs(s2)));
}

// value.x: the map's scalar (k1 for the principal map), value.y: k2.
vec3 colormap_color(int map, vec2 value, float range) {
    range = max(range, 1e-30);
    if (map == 5) return principal_colors(value.x, value.y, range);
    if (map == 6) return sequential(value.x / range);
    return diverging(value.x / range);
}

// The scalar a map shows at a vertex (value.y only used by the principal map).
vec2 colormap_value(int map, vec2 k, vec4 C) {
    if (map == 1) return vec2(k.x, 0.0);
    if (map == 2) return vec2(k.y, 0.0);
    if (map == 3) return vec2(0.5 * (k.x + k.y), 0.0);
    if (map == 4) return vec2(k.x * k.y, 0.0);
    if (map == 5) return k;
    if (map == 6) return vec2(sqrt(C.x * C.x + 3.0 * C.y * C.y + 3.0 * C.z * C.z + C.w * C.w), 0.0);
    return vec2(0.0);
}
