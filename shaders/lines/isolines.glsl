// Occluding and suggestive contours, per triangle (the geometry stage,
// isolines_geom.glsl, or a compute pass, triangles_comp.glsl): the
// segment where a linearly interpolated per-vertex field crosses zero.
//   contours:   n.v = 0
//   suggestive: kr = 0, kept where Dw kr * fs^2 > threshold and n.v > 0
//               (front-facing; conventions.md). The segment is clipped where
//               the test fails inside it, as rtsc does.
//   suggestive highlights (DeCarlo and Rusinkiewicz 2007): kr = 0 where
//               -Dw kr * fs^2 > the highlight threshold and n.v > 0, the
//               other half of the zeros of kr;
//   dwkr:       Dw kr * fs^2 = the suggestive-contour threshold, n.v > 0
//               (where suggestive contours begin to pass the test).

LineVertex tri[3];  // the triangle being cut

uniform int u_contours;
uniform int u_silhouette_only;  // contours only where they border the background
uniform int u_suggestive;
uniform float u_sc_threshold;  // dimensionless s
uniform int u_fade;            // fade suggestive contours whose strength is close to s
uniform int u_highlights;      // suggestive highlights
uniform float u_sh_threshold;  // their dimensionless threshold
uniform int u_dwkr;            // the lines Dw kr fs^2 = s

// A zero crossing on an edge: the point mix(P[lo], P[hi], s). The edge is
// always walked from the endpoint with the smaller vertex id, so the two
// triangles sharing an edge compute the same point bit for bit (no cracks).
struct Crossing {
    int lo, hi;
    float s;
};

Crossing edge_zero(int i, int j, float f[3]) {
    Crossing c;
    c.lo = tri_id[i] < tri_id[j] ? i : j;
    c.hi = c.lo == i ? j : i;
    c.s = f[c.lo] / (f[c.lo] - f[c.hi]);
    return c;
}

// The two edges of the triangle crossed by the zero set of f. Vertex values
// are classified as f > 0 or not, so there are always 0 or 2 crossings;
// returns false when there are none.
bool find_crossings(float f[3], out Crossing c0, out Crossing c1) {
    int n = 0;
    for (int i = 0; i < 3; ++i) {
        int j = (i + 1) % 3;
        if ((f[i] > 0.0) != (f[j] > 0.0)) {
            if (n == 0) c0 = edge_zero(i, j, f);
            else c1 = edge_zero(i, j, f);
            ++n;
        }
    }
    return n == 2;
}

float lerp_at(Crossing c, float values[3]) { return mix(values[c.lo], values[c.hi], c.s); }
vec4 clip_at(Crossing c) { return mix(tri_clip[c.lo], tri_clip[c.hi], c.s); }

uniform float u_scale_tolerance;  // detail (px) x pixel size per unit of camera distance; 0 without detail

// Occlusion tolerance: half the longest edge (a smooth contour can lie that
// far behind the polygonal surface drawn in the depth buffer), or the scale
// of the fields (with --detail, lines follow the surface smoothed at that
// scale and can lie that far behind its polygons).
float triangle_tolerance() {
    float l = max(max(distance(tri[0].position, tri[1].position), distance(tri[1].position, tri[2].position)),
                  distance(tri[2].position, tri[0].position));
    float w = max(max(tri_clip[0].w, tri_clip[1].w), tri_clip[2].w);
    return max(0.5 * l, u_scale_tolerance * w);
}

void contour_segment() {
    float f[3] = float[3](tri[0].contour_ndotv, tri[1].contour_ndotv, tri[2].contour_ndotv);
    Crossing c0, c1;
    if (!find_crossings(f, c0, c1)) return;
    exterior_only_ = float(u_silhouette_only);
    emit_segment(clip_at(c0), clip_at(c1), 1.0, 1.0, triangle_tolerance());
    exterior_only_ = 0.0;
}

// Clips the segment [0, 1] to where the linear function g (g0 at 0, g1 at 1)
// is positive; returns false when nothing is left.
bool clip_positive(float g0, float g1, inout vec2 range) {
    if (g0 <= 0.0 && g1 <= 0.0) return false;
    if (g0 > 0.0 && g1 > 0.0) return true;
    float s = g0 / (g0 - g1);  // where g = 0
    if (g0 > 0.0) range.y = min(range.y, s);
    else range.x = max(range.x, s);
    return range.x < range.y;
}

// The zero set of kr kept where sign * Dw kr fs^2 - threshold > 0 and n.v > 0
// (sign 1: suggestive contours, -1: suggestive highlights).
void suggestive_segment(float sign, float threshold) {
    if (tri[0].unreliable + tri[1].unreliable + tri[2].unreliable > 0.0) return;
    float f[3] = float[3](tri[0].kr, tri[1].kr, tri[2].kr);
    Crossing x0, x1;
    if (!find_crossings(f, x0, x1)) return;
    float strength[3] = float[3](tri[0].sc_strength, tri[1].sc_strength, tri[2].sc_strength);
    float ndotv[3] = float[3](tri[0].ndotv, tri[1].ndotv, tri[2].ndotv);
    // Test values at the two crossing points, linear along the segment.
    float g0 = sign * lerp_at(x0, strength) - threshold;
    float g1 = sign * lerp_at(x1, strength) - threshold;
    vec2 range = vec2(0.0, 1.0);
    if (!clip_positive(g0, g1, range)) return;
    if (!clip_positive(lerp_at(x0, ndotv), lerp_at(x1, ndotv), range)) return;
    vec4 c0 = clip_at(x0), c1 = clip_at(x1);
    float a0 = 1.0, a1 = 1.0;
    if (u_fade != 0) {
        // Opacity rises from 0 at the threshold to 1 at twice the threshold
        // (or threshold + 0.05 for small thresholds): weak lines fade out.
        float ramp = max(threshold, 0.05);
        a0 = clamp(mix(g0, g1, range.x) / ramp, 0.0, 1.0);
        a1 = clamp(mix(g0, g1, range.y) / ramp, 0.0, 1.0);
    }
    emit_segment(mix(c0, c1, range.x), mix(c0, c1, range.y), a0, a1, triangle_tolerance());
}

// Dw kr fs^2 = s on the front-facing side, not faded (as rtsc).
void dwkr_segment() {
    if (tri[0].unreliable + tri[1].unreliable + tri[2].unreliable > 0.0) return;
    float f[3] = float[3](tri[0].sc_strength - u_sc_threshold, tri[1].sc_strength - u_sc_threshold,
                          tri[2].sc_strength - u_sc_threshold);
    Crossing x0, x1;
    if (!find_crossings(f, x0, x1)) return;
    float ndotv[3] = float[3](tri[0].ndotv, tri[1].ndotv, tri[2].ndotv);
    vec2 range = vec2(0.0, 1.0);
    if (!clip_positive(lerp_at(x0, ndotv), lerp_at(x1, ndotv), range)) return;
    vec4 c0 = clip_at(x0), c1 = clip_at(x1);
    emit_segment(mix(c0, c1, range.x), mix(c0, c1, range.y), 1.0, 1.0, triangle_tolerance());
}

void extract_isolines() {
    if (u_contours != 0) contour_segment();
    if (u_suggestive != 0) suggestive_segment(1.0, u_sc_threshold);
#ifdef KAPPA_HIGHLIGHTS
    if (u_highlights != 0) suggestive_segment(-1.0, u_sh_threshold);
    if (u_dwkr != 0) dwkr_segment();
#endif
}
