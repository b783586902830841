// Colour bar: the map's colours from the bottom (low) to the top (high) with
// a one-pixel dark frame and a tick at zero for signed maps. The principal
// map is two-dimensional: x is k1, y is k2, over [-range, range]^2 (only
// k1 >= k2 occurs, the other half is left blank).
in vec2 v_uv;
uniform int u_colormap;
uniform float u_map_range;
uniform vec4 u_rect;

out vec4 o_color;

void main() {
    vec2 px = v_uv * u_rect.zw;  // pixels from the bar's corner
    if (px.x < 1.0 || px.y < 1.0 || px.x > u_rect.z - 1.0 || px.y > u_rect.w - 1.0) {
        o_color = vec4(0.2, 0.2, 0.2, 1.0);
        return;
    }
    vec3 c;
    if (u_colormap == 5) {
        vec2 k = (v_uv * 2.0 - 1.0) * u_map_range;
        c = k.x >= k.y ? colormap_color(5, k, u_map_range) : vec3(1.0);
    } else if (u_colormap == 6) {
        c = colormap_color(6, vec2(v_uv.y * u_map_range, 0.0), u_map_range);
    } else {
        c = colormap_color(u_colormap, vec2((v_uv.y * 2.0 - 1.0) * u_map_range, 0.0), u_map_range);
        // Zero: the pixel row at the middle, the lower one where the middle falls between two
        // rows; from the exact pixel centres (gl_FragCoord), not the interpolated v_uv, which
        // rasterisers round differently.
        float d = gl_FragCoord.y - (u_rect.y + 0.5 * u_rect.w);
        if (d >= -0.5 && d < 0.5) c = vec3(0.2);
    }
    o_color = vec4(c, 1.0);
}
