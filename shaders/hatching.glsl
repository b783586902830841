// Principal-direction hatching in screen space. Strokes run along the
// projected principal direction, spaced `spacing` pixels apart; their width
// grows with the darkness of the tone (a tonal art map in one function), so
// stroke density follows the shading. The stripe phase is measured from
// the centre of a screen cell and blended across neighbouring cells: a
// single global origin would bend and crowd the strokes far from it
// wherever the direction field turns.

float hash12(vec2 p) {
    vec3 p3 = fract(vec3(p.xyx) * 0.1031);
    p3 += dot(p3, p3.yzx + 33.33);
    return fract((p3.x + p3.y) * p3.z);
}

// Ink in [0, 1] of strokes along the doubled-angle direction `dd` at pixel p.
float stroke_layer(vec2 p, vec2 dd, float darkness, float spacing) {
    float len = length(dd);
    if (len < 1e-3 || darkness <= 0.0) return 0.0;
    float angle = 0.5 * atan(dd.y, dd.x);
    vec2 across = vec2(-sin(angle), cos(angle));  // perpendicular to the strokes
    float half_width = 0.5 * darkness;            // fraction of the spacing
    float aa = 0.75 / spacing;                    // ~1 pixel in phase units
    float cell = 4.0 * spacing;
    vec2 g = p / cell - 0.5;
    vec2 base = floor(g), f = fract(g);
    float ink = 0.0;
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) {
            vec2 id = base + vec2(i, j);
            vec2 center = (id + 0.5) * cell;
            float phase = dot(p - center, across) / spacing + hash12(id);
            float d = abs(fract(phase) - 0.5);  // distance to the stroke centre, spacing units
            float stroke = 1.0 - smoothstep(half_width - aa, half_width + aa, d);
            vec2 w2 = mix(1.0 - f, f, vec2(i, j));
            ink += stroke * w2.x * w2.y;
        }
    // Blending halves the contrast between cells; restore it, and fade out
    // where neighbouring directions disagree (|dd| small: umbilics).
    return clamp(ink * 1.25, 0.0, 1.0) * smoothstep(0.2, 0.6, len);
}

// mode: 1 min (strokes along d2), 2 max (along d1), 3 cross (d1, then d2 in darker tones).
float hatch_ink(int mode, vec2 p, vec4 dirs, float tone, float spacing) {
    float darkness = clamp((0.9 - tone) / 0.9, 0.0, 1.0);
    if (mode == 1) return stroke_layer(p, dirs.zw, darkness, spacing);
    if (mode == 2) return stroke_layer(p, dirs.xy, darkness, spacing);
    float first = stroke_layer(p, dirs.xy, darkness, spacing);
    float second = stroke_layer(p, dirs.zw, clamp(2.0 * darkness - 0.6, 0.0, 1.0), spacing);
    return max(first, second);
}
