// A per-edge line family as a compute pass, one invocation an edge
// (render/lines/segment_buffer.h): KAPPA_BOUNDARIES, the open boundary
// edges (vertex index pairs, the vertices' attributes from the vertex
// buffer), or KAPPA_CREASES, the sharp edges (per end point its position and
// the normals of the edge's two faces: 9 floats, as render/fields/mesh_buffers.cpp
// uploads them). The same extraction as their geometry stages.
layout(local_size_x = 64) in;
#ifdef KAPPA_BOUNDARIES
layout(std430, binding = 1) readonly buffer Edges { uint edge_vertex[]; };
#else
layout(std430, binding = 1) readonly buffer Creases { float crease_data[]; };
uniform vec3 u_eye;  // model coordinates
#endif
uniform mat4 u_mvp;
uniform int u_item_count;  // edges

void main() {
    // Groups in rows of at most 65535 (render/lines/segment_buffer.cpp).
    uint e = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (e >= uint(u_item_count)) return;
    for (int i = 0; i < 2; ++i) {
#ifdef KAPPA_BOUNDARIES
        fetch_attributes(edge_vertex[2u * e + uint(i)]);
        edge_position[i] = a_position;
#else
        uint at = (2u * e + uint(i)) * 9u;
        vec3 p = vec3(crease_data[at], crease_data[at + 1u], crease_data[at + 2u]);
        vec3 v = u_eye - p;
        edge_position[i] = p;
        edge_facing_a[i] = dot(vec3(crease_data[at + 3u], crease_data[at + 4u], crease_data[at + 5u]), v);
        edge_facing_b[i] = dot(vec3(crease_data[at + 6u], crease_data[at + 7u], crease_data[at + 8u]), v);
#endif
        edge_clip[i] = u_mvp * vec4(edge_position[i], 1.0);
    }
#ifdef KAPPA_BOUNDARIES
    extract_boundary();
#else
    extract_crease();
#endif
}
