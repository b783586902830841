// A per-triangle line family as a compute pass, one invocation a triangle of
// the clusters that can hold its lines (render/lines/cluster_culling.h): the
// family's per-vertex quantities (KAPPA_VERTEX, e.g. line_vertex) at the
// three corners, then its extraction (KAPPA_EXTRACT, e.g. extract_isolines),
// which hands its segments to segment_append.glsl. The same functions as the
// geometry stage's, so the segments are the same.
layout(local_size_x = 64) in;
layout(std430, binding = 1) readonly buffer Triangles { uint triangle_vertex[]; };  // the element buffer
// The runs of faces to cut: (first face, faces in the runs before it), sorted.
layout(std430, binding = 2) readonly buffer FaceRuns { uvec2 face_runs[]; };
uniform int u_run_count;
uniform int u_face_total;  // faces in all the runs

void main() {
    // Groups in rows of at most 65535 (render/lines/segment_buffer.cpp).
    uint g = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (g >= uint(u_face_total)) return;
    // The last run that starts at or before g.
    uint lo = 0u, hi = uint(u_run_count) - 1u;
    while (lo < hi) {
        uint mid = (lo + hi + 1u) / 2u;
        if (face_runs[mid].y <= g) lo = mid;
        else hi = mid - 1u;
    }
    uint face = face_runs[lo].x + (g - face_runs[lo].y);
    for (int i = 0; i < 3; ++i) {
        uint vertex = triangle_vertex[3u * face + uint(i)];
        fetch_attributes(vertex);
        tri[i] = KAPPA_VERTEX();
        tri_id[i] = int(vertex);
        tri_clip[i] = u_mvp * vec4(a_position, 1.0);
    }
    KAPPA_EXTRACT();
}
