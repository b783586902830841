// Shader hatching, full-screen stage: the strokes of shader_hatching.glsl,
// evaluated once a pixel from the targets the surface pass filled
// (surface_frag.glsl with KAPPA_HATCH_TARGETS), as line coverage (blended
// with GL_MAX into the line buffer, where the compositor inks it like every
// line).
uniform sampler2D u_directions;
uniform sampler2D u_darkness;

out float o_coverage;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float darkness = texelFetch(u_darkness, pixel, 0).r;
    if (darkness < 0.125) discard;  // background, back-facing, or too light for strokes
    float coverage = hatch_coverage(gl_FragCoord.xy, darkness, texelFetch(u_directions, pixel, 0));
    if (coverage <= 0.0) discard;
    o_coverage = coverage;
}
