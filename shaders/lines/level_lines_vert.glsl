// The vertex stage of level_lines_geom.glsl: level_vertex.glsl per vertex.
out LevelVertexBlock {
    LevelVertex v;
} v_out;

void main() {
    v_out.v = level_vertex();
    gl_Position = u_mvp * vec4(a_position, 1.0);
}
