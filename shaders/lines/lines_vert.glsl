// Line passes, vertex stage: the per-vertex quantities of line_vertex.glsl
// for the geometry shader that extracts zero crossings (isolines_geom.glsl).
out LineVertexBlock {
    LineVertex v;
    flat int id;  // vertex index: fixes the order in which shared edges are cut
} v_out;

void main() {
    v_out.v = line_vertex();
    v_out.id = gl_VertexID;
    gl_Position = u_mvp * vec4(a_position, 1.0);
}
