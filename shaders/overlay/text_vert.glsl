// Text labels: glyph quads in window pixels with their atlas coordinates.
layout(location = 0) in vec2 a_position;  // pixels, origin bottom left
layout(location = 1) in vec2 a_uv;
uniform vec2 u_viewport;
out vec2 v_uv;

void main() {
    v_uv = a_uv;
    gl_Position = vec4(a_position / u_viewport * 2.0 - 1.0, 0.0, 1.0);
}
