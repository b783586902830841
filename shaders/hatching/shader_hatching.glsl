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

// A software rasteriser pays for every operation of this file, once for
// each fragment of every small triangle: each is shared where it can be, and
// the functions below are as cheap as the strokes allow.

// The hashes of the four cells home + (0,0), (1,0), (0,1), (1,1) start from
// one linear key (x A + y B, then A, B or A + B added) and are mixed on their
// own; each gives a point of [0, 1)^2 from its bits (signed conversions:
// unsigned ones are emulated).
const uint HATCH_KEY_X = 0x8da6b343u, HATCH_KEY_Y = 0xd8163841u;

vec2 cell_point(uint key) {
    uint h = (key ^ (key >> 15u)) * 0x2c1b3c6du;
    h ^= h >> 12u;
    return vec2(ivec2(h & 0xffffu, h >> 16u)) * (1.0 / 65536.0);
}

// (cos 2 pi t, sin 2 pi t) / 8, within 6% (a parabola a quarter turn): the
// phasors need the turn's direction, not an exact sine.
vec2 turn8(float t) {
    float u = t - floor(t + 0.5);              // [-1/2, 1/2)
    float v = u + (u < 0.25 ? 0.25 : -0.75);   // u + 1/4 wrapped the same way
    return vec2(v - 2.0 * v * abs(v), u - 2.0 * u * abs(u));
}

// The phasor sums of both families at window point p (strokes across unit
// vectors across1 and across2, wavelength `spacing` pixels), as (re, im)
// pairs, and the sum of the kernels' weights. The kernels sit one to a cell
// of two wavelengths, each at a random point of its cell that anchors its
// phase, and each weighs the 2 x 2 cells around it with a smooth window that
// vanishes where p leaves them: the four kernels nearest p make the whole
// sum, and the pattern has no seams. In cell units p lies at home + f
// (centres at integers, f in [0, 1)^2): the windows' factors are (1 - t^2)^2
// at t = f for the home cells and t = 1 - f for the next ones, and the
// kernel of cell home + o lies 2 (o + point - f) - 1 wavelengths from p.
vec4 phasor_sums(vec2 p, vec2 across1, vec2 across2, float spacing, bool second, out float weight) {
    vec2 q = p * (0.5 / spacing) - 0.5;
    vec2 home = floor(q);
    vec2 f = q - home;
    vec2 near = 1.0 - f * f, far = f * (2.0 - f);
    near *= near, far *= far;
    weight = (near.x + far.x) * (near.y + far.y);
    vec2 at = 2.0 * f + 1.0;  // p from the home cell's corner, in wavelengths
    float base1 = dot(at, across1), base2 = dot(at, across2);
    uint key = uint(int(home.x)) * HATCH_KEY_X + uint(int(home.y)) * HATCH_KEY_Y;
    vec4 sums = vec4(0.0);
    for (int i = 0; i < 4; ++i) {
        vec2 o = vec2(i & 1, i >> 1);
        uint cell_key = key + ((i & 1) != 0 ? HATCH_KEY_X : 0u) + ((i & 2) != 0 ? HATCH_KEY_Y : 0u);
        float g = ((i & 1) != 0 ? far.x : near.x) * ((i & 2) != 0 ? far.y : near.y);
        vec2 kernel = 2.0 * (o + cell_point(cell_key));
        sums.xy += g * turn8(base1 - dot(kernel, across1));
        if (second) sums.zw += g * turn8(base2 - dot(kernel, across2));
    }
    return sums;
}

// Coverage in [0, 1] of a family's strokes from its phasor sum: the distance
// to the stroke's centre line (phase 0) in pixels; where the kernels cancel,
// the phase is undefined: no stroke there (the coherence ramps from 0 to 1
// as |sum| coherence_scale goes from 0.25 to 1.25). The phase's size is twice the
// arctangent of tan(phase / 2) = |im| / (|sum| + re), taken as x (pi/4 +
// 0.273 (1 - x)) on [0, 1] and from pi/2 less it above (within 0.004 rad).
float stroke_coverage(vec2 sum, float coherence_scale, float spacing, float width) {
    float len = length(sum);
    float a = abs(sum.y), b = len + sum.x;
    float x = min(a, b) / max(max(a, b), 1e-20);
    float half_phase = x * (0.7853982 + 0.273 * (1.0 - x));
    if (a > b) half_phase = 1.5707963 - half_phase;
    float distance_px = half_phase * spacing * (1.0 / HATCH_PI);
    float coherence = clamp(len * coherence_scale - 0.25, 0.0, 1.0);
    return coherence * clamp(0.5 * width + 0.5 - distance_px, 0.0, 1.0);
}

// The direction across the strokes from a doubled-angle vector (cos 2a, sin
// 2a) w: the direction itself (half the angle: (1 + cos 2a, sin 2a) points
// along it, as does (sin 2a, 1 - cos 2a); the larger of the two is taken)
// turned by 90 degrees. A small bias towards 2a = 90 degrees turns it to 45
// degrees where it is not defined (umbilics, flat ground), as engravers hatch.
vec2 across_direction(vec2 doubled) {
    vec2 d = doubled + vec2(0.0, 0.05);
    float len = max(length(d), 1e-6), a = len + abs(d.x);
    vec2 along = d.x >= 0.0 ? vec2(a, d.y) : vec2(d.y, a);  // |along|^2 = 2 len a
    return vec2(-along.y, along.x) * inversesqrt(2.0 * len * a);
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
    // Coherence: the phasors' length over the weights', from 0.05 to 0.25 (the sums are 1/8 of it).
    float coherence_scale = 40.0 / max(weight, 1e-6);
    float coverage = stroke_coverage(sums.xy, coherence_scale, spacing, width);
    if (cross)
        coverage = max(coverage, stroke_coverage(sums.zw, coherence_scale, spacing, width) * smoothstep(0.4, 0.5, darkness));
    return ink * coverage;
}
