// After the compute line passes: the draw command draws at most the segment
// buffer's capacity, and `requested` keeps how many were made, so the CPU
// can grow the buffer (render/lines/compute_lines.h).
layout(local_size_x = 1) in;
layout(std430, binding = 4) buffer SegmentDraw {
    uint vertex_count, instance_count, first_vertex, base_instance;
    uint requested;
} segment_draw;
uniform int u_segment_capacity;

void main() {
    segment_draw.requested = segment_draw.instance_count;
    segment_draw.instance_count = min(segment_draw.instance_count, uint(u_segment_capacity));
}
