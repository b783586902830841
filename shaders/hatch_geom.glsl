// Principal-direction hatching, geometry stage: short straight strokes
// along the projected principal direction, seeded at random points of each
// triangle. The number of strokes per pixel of screen area follows the
// darkness of the Lambertian tone, so the stroke density follows the tone;
// in cross mode a second stroke along the other direction joins in the
// darker tones. Seeds are a hash of the triangle index: strokes stay on the
// same surface points from frame to frame (no "shower door" sliding) and
// each stroke keeps its place as the tone changes (it appears once the
// darkness passes its own random level).
layout(triangles) in;
layout(triangle_strip, max_vertices = 16) out;  // up to 4 strokes

in HatchVertex {
    vec3 position;
    vec3 normal;
    vec3 d1, d2;
} v_in[];

uniform mat4 u_mvp;
uniform mat3 u_normal_matrix;
uniform vec3 u_light;           // camera coordinates, unit
uniform int u_hatching;         // 1 min (along d2), 2 max (along d1), 3 cross
uniform float u_hatch_spacing;  // pixels between strokes at full darkness
uniform float u_stroke_length;  // pixels
uniform float u_stroke_width;   // pixels

uint hash(uint x) {  // integer hash (Wellons' lowbias32)
    x ^= x >> 16; x *= 0x7feb352du;
    x ^= x >> 15; x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}
float random01(uint seed) { return float(hash(seed) >> 8) * (1.0 / 16777216.0); }

// The triangle's principal direction, averaged after aligning the vertices'
// signs (directions are defined up to sign). Zero when they disagree too
// much to be meaningful (near umbilics or noise).
vec3 triangle_direction(vec3 a, vec3 b, vec3 c) {
    vec3 d = a + (dot(a, b) < 0.0 ? -b : b) + (dot(a, c) < 0.0 ? -c : c);
    float len = length(d);
    return len > 2.4 ? d / len : vec3(0.0);
}

// Window-space direction of the tangent d at the point with clip coordinates clip.
vec2 screen_direction(vec4 clip, vec3 d) {
    vec4 dc = u_mvp * vec4(d, 0.0);
    vec2 s = (dc.xy - clip.xy * (dc.w / clip.w)) / clip.w * u_viewport;
    float len = length(s);
    return len > 1e-6 ? s / len : vec2(0.0);
}

void stroke(vec4 clip, vec3 d, float tolerance) {
    if (d == vec3(0.0)) return;
    vec2 dir = screen_direction(clip, d);
    if (dir == vec2(0.0)) return;
    vec3 c = to_window(clip);
    vec3 h = vec3(dir * (0.5 * u_stroke_length), 0.0);
    emit_window_segment(c - h, c + h, 0.9, 0.9, tolerance, u_stroke_width, true);
}

void main() {
    vec4 c0 = gl_in[0].gl_Position, c1 = gl_in[1].gl_Position, c2 = gl_in[2].gl_Position;
    if (c0.w <= 0.0 || c1.w <= 0.0 || c2.w <= 0.0) return;
    vec3 w0 = to_window(c0), w1 = to_window(c1), w2 = to_window(c2);
    vec2 e1 = w1.xy - w0.xy, e2 = w2.xy - w0.xy;
    float area = 0.5 * (e1.x * e2.y - e1.y * e2.x);  // > 0: front-facing (counter-clockwise)
    if (area <= 0.0) return;

    vec3 n = normalize(u_normal_matrix * (v_in[0].normal + v_in[1].normal + v_in[2].normal));
    float tone = max(dot(n, u_light), 0.0);
    float darkness = clamp((0.95 - tone) / 0.8, 0.0, 1.0);
    float expected = area * darkness / (u_hatch_spacing * u_stroke_length);
    if (expected <= 0.0) return;

    vec3 along_d1 = triangle_direction(v_in[0].d1, v_in[1].d1, v_in[2].d1);
    vec3 along_d2 = triangle_direction(v_in[0].d2, v_in[1].d2, v_in[2].d2);
    vec3 first = u_hatching == 1 ? along_d2 : along_d1;
    float tolerance = 0.5 * max(max(distance(v_in[0].position, v_in[1].position),
                                    distance(v_in[1].position, v_in[2].position)),
                                distance(v_in[2].position, v_in[0].position));
    uint seed = uint(gl_PrimitiveIDIn) * 8u;
    int strokes = u_hatching == 3 ? 2 : 4;  // cross: up to 2 seeds with 2 strokes each
    for (int i = 0; i < strokes; ++i) {
        if (float(i) + random01(seed + uint(4 * i)) >= expected) break;
        // A uniformly random point of the triangle.
        float r1 = sqrt(random01(seed + uint(4 * i + 1))), r2 = random01(seed + uint(4 * i + 2));
        vec4 clip = (1.0 - r1) * c0 + r1 * (1.0 - r2) * c1 + r1 * r2 * c2;
        stroke(clip, first, tolerance);
        if (u_hatching == 3 && random01(seed + uint(4 * i + 3)) < (darkness - 0.4) / 0.6)
            stroke(clip, along_d2, tolerance);
    }
}
