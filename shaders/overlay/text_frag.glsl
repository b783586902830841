// Text labels: the font atlas's coverage as the alpha of one colour.
in vec2 v_uv;
uniform sampler2D u_atlas;  // one channel: glyph coverage
uniform vec3 u_color;
out vec4 o_color;

void main() {
    float a = texture(u_atlas, v_uv).r;
    if (a <= 0.0) discard;
    o_color = vec4(u_color, a);
}
