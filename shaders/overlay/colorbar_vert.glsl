// Colour bar: a rectangle in window pixels; v_uv in [0, 1]^2 across it.
uniform vec4 u_rect;  // x, y, width, height in pixels (origin bottom left)
uniform vec2 u_viewport;
out vec2 v_uv;

void main() {
    vec2 uv = vec2(gl_VertexID & 1, (gl_VertexID >> 1) & 1);
    v_uv = uv;
    vec2 p = u_rect.xy + uv * u_rect.zw;
    gl_Position = vec4(p / u_viewport * 2.0 - 1.0, 0.0, 1.0);
}
