// Principal-direction hatching, geometry stage (called from
// isolines_geom.glsl): short straight strokes along the projected principal
// direction, seeded at random points of each front-facing triangle. The
// number of strokes per pixel of screen area follows the darkness of the
// Lambertian tone, so stroke density follows the tone; in cross mode a
// second stroke along the other direction joins in the darker tones. Seeds
// are a hash of the triangle index: strokes stay on the same surface points
// from frame to frame (no "shower door" sliding) and each keeps its place
// as the tone changes (it appears once the darkness passes its own random
// level). Comes after isolines_geom.glsl, which declares v_in[] (with
// hatch_dirs and tone) and u_hatching.
uniform float u_hatch_spacing;  // pixels between strokes at full darkness
uniform float u_stroke_length;  // pixels
uniform float u_stroke_width;   // pixels

uint hash_u32(uint x) {  // integer hash (Wellons' lowbias32)
    x ^= x >> 16; x *= 0x7feb352du;
    x ^= x >> 15; x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}
float random01(uint seed) { return float(hash_u32(seed) >> 8) * (1.0 / 16777216.0); }

// The triangle's window-space stroke direction: the vertices' directions
// averaged after aligning their signs (principal directions are defined up
// to sign); zero where they disagree too much to mean anything (umbilics,
// noise).
vec2 triangle_direction(vec2 a, vec2 b, vec2 c) {
    vec2 d = a + (dot(a, b) < 0.0 ? -b : b) + (dot(a, c) < 0.0 ? -c : c);
    float len = length(d);
    return len > 2.4 ? d / len : vec2(0.0);
}

void stroke(vec4 clip, vec2 dir, float tolerance) {
    if (dir == vec2(0.0)) return;
    vec3 c = to_window(clip);
    vec3 h = vec3(dir * (0.5 * u_stroke_length), 0.0);
    emit_window_segment(c - h, c + h, 0.9, 0.9, tolerance, u_stroke_width, true);
}

void hatch_strokes(float tolerance) {
    vec4 c0 = gl_in[0].gl_Position, c1 = gl_in[1].gl_Position, c2 = gl_in[2].gl_Position;
    if (c0.w <= 0.0 || c1.w <= 0.0 || c2.w <= 0.0) return;
    vec3 w0 = to_window(c0), w1 = to_window(c1), w2 = to_window(c2);
    vec2 e1 = w1.xy - w0.xy, e2 = w2.xy - w0.xy;
    float area = 0.5 * (e1.x * e2.y - e1.y * e2.x);  // > 0: front-facing (counter-clockwise)
    if (area <= 0.0) return;
    float tone = (v_in[0].tone + v_in[1].tone + v_in[2].tone) / 3.0;
    float darkness = clamp((0.95 - tone) / 0.8, 0.0, 1.0);
    float expected = area * darkness / (u_hatch_spacing * u_stroke_length);
    uint seed = uint(gl_PrimitiveIDIn) * 8u;
    if (random01(seed) >= expected) return;  // the first stroke's test, before any other work

    vec2 along_d1 = triangle_direction(v_in[0].hatch_dirs.xy, v_in[1].hatch_dirs.xy, v_in[2].hatch_dirs.xy);
    vec2 along_d2 = triangle_direction(v_in[0].hatch_dirs.zw, v_in[1].hatch_dirs.zw, v_in[2].hatch_dirs.zw);
    vec2 first = u_hatching == 1 ? along_d2 : along_d1;
    int seeds = u_hatching == 3 ? 2 : 4;  // cross: up to 2 seeds with 2 strokes each
    for (int i = 0; i < seeds; ++i) {
        if (float(i) + random01(seed + uint(4 * i)) >= expected) break;
        // A uniformly random point of the triangle.
        float r1 = sqrt(random01(seed + uint(4 * i + 1))), r2 = random01(seed + uint(4 * i + 2));
        vec4 clip = (1.0 - r1) * c0 + r1 * (1.0 - r2) * c1 + r1 * r2 * c2;
        stroke(clip, first, tolerance);
        if (u_hatching == 3 && random01(seed + uint(4 * i + 3)) < (darkness - 0.4) / 0.6)
            stroke(clip, along_d2, tolerance);
    }
}
