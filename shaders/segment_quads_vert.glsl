// Line segments made on the CPU (render/cpu_lines.h), drawn without a
// geometry shader: each segment comes as four vertices (two triangles), all
// with both end points, and each vertex puts itself at one corner of the
// quad that line_quad.glsl's emit_window_segment would emit. Software
// renderers run geometry shaders one primitive at a time on one thread;
// this runs as an ordinary vertex shader. lines_frag.glsl is unchanged.
layout(location = 0) in vec3 a_end0;      // model coordinates
layout(location = 1) in vec3 a_end1;
layout(location = 2) in vec2 a_alpha;     // opacity at the two ends
layout(location = 3) in float a_tolerance;  // model units
layout(location = 4) in float a_kind_corner;  // 4 kind + corner: kind as segments_vert.glsl's a_kind (0, 1, 2),
                                              // corner 0..3: (end, side) = (0,-), (0,+), (1,-), (1,+)

uniform mat4 u_mvp;
uniform vec2 u_viewport;          // pixels
uniform float u_line_width;       // pixels
uniform float u_scale_tolerance;  // detail (px) x pixel size per unit of camera distance; 0 without detail
uniform int u_silhouette_only;    // contours only where they border the background

out LineFragment {
    flat vec4 segment;
    flat vec2 depth;
    flat vec2 alpha;
    flat float tolerance;
    flat float width;
    flat float on_surface;
    flat float exterior_only;
} v_out;

vec3 to_window(vec4 clip) {
    vec3 ndc = clip.xyz / clip.w;
    return vec3((ndc.xy * 0.5 + 0.5) * u_viewport, ndc.z * 0.5 + 0.5);
}

void main() {
    int code = int(a_kind_corner + 0.5);
    float kind = float(code / 4);
    int corner = code - 4 * (code / 4);
    vec4 clip0 = u_mvp * vec4(a_end0, 1.0), clip1 = u_mvp * vec4(a_end1, 1.0);
    v_out.alpha = a_alpha;
    v_out.width = u_line_width;
    v_out.on_surface = 0.0;
    v_out.exterior_only = kind > 1.5 && u_silhouette_only != 0 ? 1.0 : 0.0;
    float w = max(clip0.w, clip1.w);
    v_out.tolerance = max(a_tolerance, kind > 0.5 ? u_scale_tolerance * w : 0.0);
    if (clip0.w <= 0.0 || clip1.w <= 0.0) {  // (segments without ink are never uploaded)
        gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // behind the eye: a degenerate quad outside the view
        v_out.segment = vec4(0.0), v_out.depth = vec2(0.0);
        return;
    }
    vec3 p0 = to_window(clip0), p1 = to_window(clip1);
    vec2 dir = p1.xy - p0.xy;
    float len = length(dir);
    dir = len > 1e-6 ? dir / len : vec2(1.0, 0.0);
    vec2 nrm = vec2(-dir.y, dir.x);
    float r = 0.5 * u_line_width + 0.5;  // lines_frag.glsl gives no coverage farther from the centre line
    v_out.segment = vec4(p0.xy, p1.xy);
    v_out.depth = vec2(p0.z, p1.z);
    float z = min(p0.z, p1.z);  // any depth inside the range: depth testing is done in lines_frag
    vec2 xy = corner < 2 ? p0.xy - dir * r : p1.xy + dir * r;
    xy += (corner == 0 || corner == 2 ? -nrm : nrm) * r;
    gl_Position = vec4(xy / u_viewport * 2.0 - 1.0, z * 2.0 - 1.0, 1.0);
}
