// Vector glyphs, geometry stage: from each kept vertex, short strokes of
// u_glyph pixels along the chosen directions (bits of u_vectors): 1 normal,
// 2 first principal direction, 4 second, 8 asymptotic directions (where
// K < 0: the two tangents along which the normal curvature is zero,
// tan^2 = -k1 / k2 from d1), 16 the view direction. Directions seen
// end-on draw nothing. Hidden glyphs are removed like every line.
layout(points) in;
layout(triangle_strip, max_vertices = 24) out;

in GlyphVertex {
    vec3 position, normal, d1, d2, view;
    vec2 curv;
    float keep;
} v_in[];

uniform mat4 u_mvp;
uniform int u_vectors;
uniform float u_glyph;  // pixels

void stroke(vec3 dir, bool both_ways) {
    vec4 c0 = gl_in[0].gl_Position;
    if (c0.w <= 0.0) return;
    // A tiny step along dir, projected: the stroke's direction on screen.
    float step = 1e-3 * c0.w;
    vec4 c1 = u_mvp * vec4(v_in[0].position + step * dir, 1.0);
    vec3 w0 = to_window(c0), w1 = to_window(c1);
    vec2 d = w1.xy - w0.xy;
    float len = length(d);
    // Seen end-on: a step across the view moves about u_viewport.y / 1000 px;
    // one along it (the view direction itself) a rounding error.
    if (len < 1e-5 * u_viewport.y) return;
    vec2 end = w0.xy + d / len * u_glyph;
    vec2 start = both_ways ? w0.xy - d / len * u_glyph : w0.xy;
    // Occlusion tolerance: twice the stroke's length in model units (the
    // surface under a stroke curves away from the vertex's depth).
    float tolerance = 2.0 * u_glyph * step / len;
    emit_window_segment(vec3(start, w0.z), vec3(end, w0.z), 1.0, 1.0, tolerance, u_line_width, false);
}

void main() {
    if (v_in[0].keep == 0.0) return;
    if ((u_vectors & 1) != 0) stroke(v_in[0].normal, false);
    if ((u_vectors & 2) != 0) stroke(v_in[0].d1, true);
    if ((u_vectors & 4) != 0) stroke(v_in[0].d2, true);
    if ((u_vectors & 8) != 0 && v_in[0].curv.x * v_in[0].curv.y < 0.0) {
        float t = sqrt(-v_in[0].curv.x / v_in[0].curv.y);  // tan of the angle from d1
        vec3 a = normalize(v_in[0].d1 + t * v_in[0].d2), b = normalize(v_in[0].d1 - t * v_in[0].d2);
        stroke(a, true);
        stroke(b, true);
    }
    if ((u_vectors & 16) != 0) stroke(v_in[0].view, false);
}
