// Principal-direction hatching, geometry stage: a kept surface sample
// (hatch_vert.glsl) becomes one or two anti-aliased strokes, drawn only
// over the surface and hidden where it is occluded (lines_frag.glsl).
layout(points) in;
layout(triangle_strip, max_vertices = 8) out;

in HatchSample {
    vec4 first;
    vec4 second;
    float tolerance;
} s_in[];

uniform float u_stroke_width;  // pixels

void stroke(vec4 centre, vec4 half_stroke) {
    if (half_stroke == vec4(0.0)) return;
    vec4 a = centre - half_stroke, b = centre + half_stroke;
    if (a.w <= 0.0 || b.w <= 0.0) return;  // behind the eye
    emit_window_segment(to_window(a), to_window(b), 0.9, 0.9, s_in[0].tolerance, u_stroke_width, true);
}

void main() {
    stroke(gl_in[0].gl_Position, s_in[0].first);
    stroke(gl_in[0].gl_Position, s_in[0].second);
}
