// Hatching drawn on the GPU (--hatch-style shader, and the viewer while the
// view moves; render/hatching/shader_hatching.h): no readback and no tracing
// on the CPU, once a pixel. Strokes run along the principal direction projected into the
// window, two spacings apart (the streamlines' spacing at half darkness,
// render/hatching/hatch_streamlines.h); the tone is in their width and ink,
// as an engraver swells a line, from nothing below darkness 1/8 (where the
// streamlines stop too) to the full stroke width at 0.8; the cross family
// only where the tone is 0.4 dark or more, as the streamlines'.
//
// Why one spacing and not `spacing / darkness` as the streamlines: the tone
// changes over a few pixels on a bumpy surface, and a wavelength that
// follows it bends the stripes into a crackle.
//
// The strokes are the level lines of the phase of a phasor noise (Tricard,
// Efremov, Zanni, Neyret, Martinez and Lefebvre 2019, "Procedural phasor
// noise"): a sum of Gabor kernels on a grid of cells, each a complex
// sinusoid across the stroke direction under a smooth window; its phase makes
// stripes of even contrast and spacing that bend with the direction field,
// where a sum of the kernels' real parts (Gabor noise) would fade in and
// out. Each pixel evaluates the kernels around it with its own direction
// (the principal direction interpolated over the triangle, as a doubled
// angle): the stripes follow it as long as it turns slowly across a kernel
// (two wavelengths).
// The pattern is fixed to the window, so it slides over the surface as the
// view moves; the streamlines drawn at rest are attached to the surface.
uniform int u_hatching;         // 0 none, 1 along d1 (max), 2 along d2 (min), 3 cross (both)
uniform float u_hatch_spacing;  // pixels between strokes in the darkest tone
uniform float u_hatch_width;    // stroke width, pixels

const float HATCH_PI = 3.14159265358979;

// A hash of a cell to [0, 1)^2 (integer mixing, no trigonometry).
vec2 cell_hash(ivec2 cell) {
    uint h = uint(cell.x) * 0x8da6b343u ^ uint(cell.y) * 0xd8163841u;
    h = (h ^ (h >> 15u)) * 0x2c1b3c6du;
    h ^= h >> 12u;
    return vec2(h & 0xffffu, h >> 16u) * (1.0 / 65536.0);
}

// (cos 2 pi t, sin 2 pi t), within 6% (a parabola a quarter turn): the
// phasors need the turn's direction, not an exact sine, and a software
// rasteriser pays for every exact one.
vec2 turn(float t) {
    float u = t - floor(t + 0.5);                // [-1/2, 1/2)
    float v = u + 0.25 - floor(u + 0.75);        // u + 1/4 wrapped the same way
    return 8.0 * vec2(v * (1.0 - 2.0 * abs(v)), u * (1.0 - 2.0 * abs(u)));
}

// The phasor sums of both families at window point p (strokes across unit
// vectors across1 and across2, wavelength `spacing` pixels), as (re, im)
// pairs, and the sum of the kernels' weights in the last slot. The kernels
// sit one to a cell of two wavelengths, each at a random point of its cell
// that anchors its phase, and each weighs the 2 x 2 cells around it with a
// smooth window that vanishes where p leaves them: the four kernels nearest
// p make the whole sum, and the pattern has no seams.
vec4 phasor_sums(vec2 p, vec2 across1, vec2 across2, float spacing, bool second, out float weight) {
    float cell_size = 2.0 * spacing;
    vec2 q = p / cell_size - 0.5;  // cell units, cell centres at integers
    vec2 home = floor(q);
    vec4 sums = vec4(0.0);
    weight = 0.0;
    for (int i = 0; i < 4; ++i) {
        vec2 cell = home + vec2(i & 1, i >> 1);
        vec2 t = abs(q - cell);  // < 1 on both axes
        vec2 b = (1.0 - t * t) * (1.0 - t * t);
        float g = b.x * b.y;
        vec2 r = (p - (cell + cell_hash(ivec2(cell))) * cell_size) / spacing;
        sums.xy += g * turn(dot(r, across1));
        if (second) sums.zw += g * turn(dot(r, across2));
        weight += g;
    }
    return sums;
}

// |atan2(y, x)| in [0, pi], within 0.0003 rad of it (a polynomial in the
// smaller-over-larger ratio): the stroke profile needs no more, and a
// software rasteriser pays for every exact arctangent.
float abs_angle(vec2 v) {
    vec2 a = abs(v);
    float t = min(a.x, a.y) / max(max(a.x, a.y), 1e-20), t2 = t * t;
    float r = ((-0.0464964749 * t2 + 0.15931422) * t2 - 0.327622764) * t2 * t + t;
    if (a.y > a.x) r = 1.57079637 - r;
    return v.x < 0.0 ? 3.14159274 - r : r;
}

// Coverage in [0, 1] of a family's strokes from its phasor sum: the distance
// to the stroke's centre line (phase 0) in pixels; where the kernels cancel,
// the phase is undefined: no stroke there.
float stroke_coverage(vec2 sum, float weight, float spacing, float width) {
    float distance_px = abs_angle(sum) * spacing / (2.0 * HATCH_PI);
    float coherence = smoothstep(0.05, 0.25, length(sum) / max(weight, 1e-6));
    return coherence * clamp(0.5 * width + 0.5 - distance_px, 0.0, 1.0);
}

// The direction across the strokes from a doubled-angle vector (cos 2a, sin
// 2a) w: the direction itself (half the angle, by the half-angle formulas)
// turned by 90 degrees; 45 degrees where it is not defined (umbilics, flat
// ground), as engravers hatch.
vec2 across_direction(vec2 doubled) {
    float w = length(doubled);
    vec2 cs = w > 1e-6 ? doubled / w : vec2(0.0, 1.0);
    vec2 along = vec2(sqrt(max(0.5 + 0.5 * cs.x, 0.0)), sqrt(max(0.5 - 0.5 * cs.x, 0.0)));
    if (cs.y < 0.0) along.y = -along.y;
    along = normalize(mix(vec2(0.70710678), along, smoothstep(0.05, 0.3, w)) + vec2(1e-7, 0.0));
    return vec2(-along.y, along.x);
}

// The hatching's coverage at window point p: darkness in [0, 1] (the tone),
// hatch_dirs the doubled window angles of d1 and d2 times their reliability.
float hatch_coverage(vec2 p, float darkness, vec4 hatch_dirs) {
    if (u_hatching == 0 || darkness < 0.125) return 0.0;  // streamlines would be more than 8 spacings apart
    float spacing = 2.0 * u_hatch_spacing;
    float swell = smoothstep(0.125, 0.8, darkness);
    float width = u_hatch_width * mix(0.4, 1.0, swell);
    float ink = mix(0.35, 1.0, swell);
    // First family along d1 (or d2 alone for min); the cross family along d2 from darkness 0.4.
    vec2 first = u_hatching == 2 ? hatch_dirs.zw : hatch_dirs.xy;
    bool cross = u_hatching == 3 && darkness >= 0.4;
    float weight;
    vec4 sums = phasor_sums(p, across_direction(first), cross ? across_direction(hatch_dirs.zw) : vec2(0.0), spacing,
                            cross, weight);
    float coverage = stroke_coverage(sums.xy, weight, spacing, width);
    if (cross) coverage = max(coverage, stroke_coverage(sums.zw, weight, spacing, width) * smoothstep(0.4, 0.5, darkness));
    return ink * coverage;
}
