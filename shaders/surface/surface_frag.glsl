// Surface pass, fragment stage: paper, Lambertian, toon (grey and white, or
// black and white), hemisphere or Gooch (cool to warm, Gooch et al. 1998)
// shading and a curvature colour map. Output is premultiplied RGBA (opaque).
// Shader hatching (KAPPA_HATCHING; streamline hatching is drawn by the line
// passes): its strokes over the colour (hatching/shader_hatching.glsl), or
// with KAPPA_HATCH_TARGETS what they need, into two more targets, for a
// full-screen pass to draw them once a pixel (render/hatching/shader_hatching.h).
in vec3 v_normal;
in vec2 v_map_value;
#ifdef KAPPA_HATCHING
in vec4 v_hatch_dirs;  // doubled window angles of d1, d2 times their reliability
#ifdef KAPPA_HATCH_TARGETS
layout(location = 1) out vec4 o_hatch_directions;
layout(location = 2) out float o_hatch_darkness;
#else
uniform vec3 u_line_color;
#endif
#endif

uniform int u_shading;      // 0 none (white paper), 1 Lambert, 2 toon, 3 hemisphere, 4 toon-bw, 5 Gooch
uniform vec3 u_light;       // unit, towards the light, camera coordinates
uniform int u_colormap;     // 0 none, else colormap.glsl ids
uniform float u_map_range;

layout(location = 0) out vec4 o_color;

void main() {
    vec3 n = normalize(v_normal);
    if (!gl_FrontFacing) n = -n;  // the inside seen through holes
    float diffuse = max(dot(n, u_light), 0.0);
    float light = 1.0;
    if (u_shading == 1) light = 0.25 + 0.75 * diffuse;
    if (u_shading == 2) light = diffuse > 0.6 ? 1.0 : (diffuse > 0.25 ? 0.75 : 0.5);
    if (u_shading == 3) light = 0.35 + 0.65 * (0.5 + 0.5 * dot(n, u_light));  // lit from the whole sky around the light
    if (u_shading == 4) light = diffuse > 0.35 ? 1.0 : 0.3;                 // two tones: lines stay readable

    vec3 albedo = u_colormap != 0 ? colormap_color(u_colormap, v_map_value, u_map_range) : vec3(1.0);
    if (u_shading == 5) {
        // Gooch: from cool blue facing away from the light to warm yellow facing it.
        float k = 0.5 + 0.5 * dot(n, u_light);
        vec3 cool = vec3(0.25, 0.3, 0.75) + 0.25 * albedo, warm = vec3(0.85, 0.75, 0.25) + 0.25 * albedo;
        o_color = vec4(min(mix(cool, warm, k), vec3(1.0)), 1.0);
    } else {
        o_color = vec4(albedo * light, 1.0);
    }
#ifdef KAPPA_HATCHING
    // The tone of the streamlines' field (render/hatching/hatch_field.h); none on back faces.
    float darkness = gl_FrontFacing ? clamp((0.95 - diffuse) / 0.8, 0.0, 1.0) : 0.0;
#ifdef KAPPA_HATCH_TARGETS
    o_hatch_directions = gl_FrontFacing ? v_hatch_dirs : vec4(0.0);
    o_hatch_darkness = darkness;
#else
    o_color.rgb = mix(o_color.rgb, u_line_color, hatch_coverage(gl_FragCoord.xy, darkness, v_hatch_dirs));
#endif
#endif
}
