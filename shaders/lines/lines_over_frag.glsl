// Final pass: lines over the surface already in the bound framebuffer
// (blending GL_ONE, GL_ONE_MINUS_SRC_ALPHA): surface * (1 - lines) +
// line_color * lines, premultiplied, nothing written where there is no line.
uniform sampler2D u_lines;  // line coverage
uniform vec3 u_line_color;

out vec4 o_color;

void main() {
    float line = texelFetch(u_lines, ivec2(gl_FragCoord.xy), 0).r;
    if (line <= 0.0) discard;
    o_color = vec4(u_line_color * line, line);
}
