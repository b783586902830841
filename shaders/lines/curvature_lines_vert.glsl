// The vertex stage of curvature_lines_geom.glsl: curvature_vertex.glsl per vertex.
out CurvatureVertexBlock {
    CurvatureVertex v;
} v_out;

void main() {
    v_out.v = curvature_vertex();
    gl_Position = u_mvp * vec4(a_position, 1.0);
}
