// A compute pass's emit_window_segment (segment_emit.glsl): the segment is
// appended to the segment buffer, three vec4 a segment, drawn afterwards by
// one indirect draw of instanced quads (segment_quads_vert.glsl with
// KAPPA_INSTANCED). The draw command's instance count is the append counter;
// segments past the capacity are counted but not stored (segment_count_comp.glsl
// clamps the count and keeps the number asked for, so the buffer can grow).
layout(std430, binding = 3) writeonly buffer Segments { vec4 segment_data[]; };
layout(std430, binding = 4) buffer SegmentDraw {
    uint vertex_count, instance_count, first_vertex, base_instance;  // DrawArraysIndirectCommand
    uint requested;
} segment_draw;
uniform int u_segment_capacity;

void emit_window_segment(vec3 p0, vec3 p1, float alpha0, float alpha1, float tolerance, float width,
                         bool on_surface) {
    if (max(alpha0, alpha1) <= 0.0) return;
    uint i = atomicAdd(segment_draw.instance_count, 1u);
    if (i >= uint(u_segment_capacity)) return;
    segment_data[3u * i] = vec4(p0, tolerance);
    segment_data[3u * i + 1u] = vec4(p1, width);
    segment_data[3u * i + 2u] = vec4(alpha0, alpha1, on_surface ? 1.0 : 0.0, exterior_only_);
}
