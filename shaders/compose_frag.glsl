// Final pass: lines over the (resolved) surface image, into the target
// framebuffer (an offscreen FBO or a window). Premultiplied alpha.
uniform sampler2D u_surface;  // premultiplied RGBA
uniform sampler2D u_lines;    // line coverage
uniform vec3 u_line_color;

out vec4 o_color;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 surface = texelFetch(u_surface, p, 0);
    float line = texelFetch(u_lines, p, 0).r;
    o_color = surface * (1.0 - line) + vec4(u_line_color, 1.0) * line;
}
