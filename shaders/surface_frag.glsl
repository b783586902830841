// Surface pass, fragment stage: paper, Lambertian or toon shading, a
// curvature colour map, principal-direction hatching. Output is
// premultiplied RGBA (opaque).
in vec3 v_normal;
in vec2 v_map_value;
in vec4 v_hatch_dirs;

uniform int u_shading;      // 0 none (white paper), 1 Lambert, 2 toon
uniform vec3 u_light;       // unit, towards the light, camera coordinates
uniform int u_colormap;     // 0 none, else colormap.glsl ids
uniform float u_map_range;
uniform int u_hatching;     // 0 none, 1 min, 2 max, 3 cross
uniform float u_hatch_spacing;

out vec4 o_color;

void main() {
    vec3 n = normalize(v_normal);
    if (!gl_FrontFacing) n = -n;  // the inside seen through holes
    float diffuse = max(dot(n, u_light), 0.0);
    float light = 1.0;
    if (u_shading == 1) light = 0.25 + 0.75 * diffuse;
    if (u_shading == 2) light = diffuse > 0.6 ? 1.0 : (diffuse > 0.25 ? 0.75 : 0.5);

    vec3 albedo = u_colormap != 0 ? colormap_color(u_colormap, v_map_value, u_map_range) : vec3(1.0);
    vec3 color = albedo * light;
    if (u_hatching != 0) {
        float ink = hatch_ink(u_hatching, gl_FragCoord.xy, v_hatch_dirs, diffuse, u_hatch_spacing);
        color *= 1.0 - 0.85 * ink;
    }
    o_color = vec4(color, 1.0);
}
