// The per-vertex attributes of mesh_attributes.glsl for a compute pass: the
// values of mesh_attribute_values.glsl read from the interleaved vertex
// buffer bound as storage (render/fields/field_upload.h, GpuVertex: 22
// floats a vertex).
layout(std430, binding = 0) readonly buffer MeshVertices { float mesh_vertex_data[]; };

vec3 vertex_vec3(uint at) { return vec3(mesh_vertex_data[at], mesh_vertex_data[at + 1u], mesh_vertex_data[at + 2u]); }

void fetch_attributes(uint vertex) {
    uint at = vertex * 22u;
    a_position = vertex_vec3(at);
    a_normal = vertex_vec3(at + 3u);
    a_d1 = vertex_vec3(at + 6u);
    a_d2 = vertex_vec3(at + 9u);
    a_curv = vec2(mesh_vertex_data[at + 12u], mesh_vertex_data[at + 13u]);
    a_dcurv = vec4(mesh_vertex_data[at + 14u], mesh_vertex_data[at + 15u], mesh_vertex_data[at + 16u],
                   mesh_vertex_data[at + 17u]);
    a_unreliable = mesh_vertex_data[at + 18u];
    a_fine_normal = vertex_vec3(at + 19u);
}
