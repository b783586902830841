// Strokes made on the CPU, geometry stage: each segment (GL_LINES) becomes a
// quad of its width (line_quad.glsl). They lie on the visible surface
// already: drawn at the near plane (never hidden), over the surface only.
layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;

in StrokeVertex {
    vec2 window;
    float width;
    float alpha;
} v_in[];

void main() {
    emit_window_segment(vec3(v_in[0].window, 0.0), vec3(v_in[1].window, 0.0), v_in[0].alpha, v_in[1].alpha, 0.0,
                        0.5 * (v_in[0].width + v_in[1].width), true);
}
