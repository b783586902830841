// Strokes made on the CPU (streamline hatching, render/hatching/hatch_streamlines.h),
// vertex stage: points already in window pixels, with their width and opacity.
layout(location = 0) in vec2 a_window;
layout(location = 1) in float a_width;
layout(location = 2) in float a_alpha;

out StrokeVertex {
    vec2 window;
    float width;
    float alpha;
} v_out;

void main() {
    v_out.window = a_window;
    v_out.width = a_width;
    v_out.alpha = a_alpha;
    gl_Position = vec4(0.0, 0.0, 0.0, 1.0);  // unused: the geometry stage works in window pixels
}
