// Line segments made on the CPU (render/lines/cpu_lines.h), drawn without a
// geometry shader: each segment comes as four vertices (two triangles), all
// with both end points in window coordinates, and each vertex puts itself at
// one corner of the quad that line_quad.glsl's emit_window_segment would
// emit. Software renderers run geometry shaders one primitive at a time on
// one thread; this runs as an ordinary vertex shader. lines_frag.glsl is
// unchanged. (On software GL the CPU draws these itself: render/lines/line_raster.h.)
layout(location = 0) in vec3 a_end0;      // window coordinates: pixels, depth
layout(location = 1) in vec3 a_end1;
layout(location = 2) in vec2 a_alpha;     // opacity at the two ends
layout(location = 3) in float a_tolerance;  // model units, the detail scale's included
layout(location = 5) in float a_width;     // pixels (the CPU's segments: 0 for u_line_width)
#ifdef KAPPA_INSTANCED
// The compute path's segments (segment_append.glsl): one instance a segment,
// its corner from the vertex index of a four-vertex triangle strip.
layout(location = 4) in float a_exterior;  // 1: exterior_only
#else
layout(location = 4) in float a_exterior_corner;  // 8 on_surface + 4 exterior_only + corner, corner 0..3:
                                                  // (end, side) = (0,-), (0,+), (1,-), (1,+)
#endif

uniform vec2 u_viewport;          // pixels
uniform float u_line_width;       // pixels

out LineFragment {
    flat vec4 segment;
    flat vec2 depth;
    flat vec2 alpha;
    flat float tolerance;
    flat float width;
    flat float on_surface;
    flat float exterior_only;
} v_out;

void main() {
#ifdef KAPPA_INSTANCED
    int corner = gl_VertexID;
    float width = a_width;
    v_out.exterior_only = a_exterior;
    v_out.on_surface = 0.0;
#else
    int code = int(a_exterior_corner + 0.5);
    int corner = code - 4 * (code / 4);
    float width = a_width > 0.0 ? a_width : u_line_width;  // hatching strokes have their own
    v_out.exterior_only = code - 8 * (code / 8) >= 4 ? 1.0 : 0.0;
    v_out.on_surface = code >= 8 ? 1.0 : 0.0;
#endif
    v_out.alpha = a_alpha;
    v_out.width = width;
    v_out.tolerance = a_tolerance;
    vec3 p0 = a_end0, p1 = a_end1;
    vec2 dir = p1.xy - p0.xy;
    float len = length(dir);
    dir = len > 1e-6 ? dir / len : vec2(1.0, 0.0);
    vec2 nrm = vec2(-dir.y, dir.x);
    float r = 0.5 * width + 0.5;  // lines_frag.glsl gives no coverage farther from the centre line
    v_out.segment = vec4(p0.xy, p1.xy);
    v_out.depth = vec2(p0.z, p1.z);
    float z = min(p0.z, p1.z);  // any depth inside the range: depth testing is done in lines_frag
    vec2 xy = corner < 2 ? p0.xy - dir * r : p1.xy + dir * r;
    xy += (corner == 0 || corner == 2 ? -nrm : nrm) * r;
    gl_Position = vec4(xy / u_viewport * 2.0 - 1.0, z * 2.0 - 1.0, 1.0);
}
