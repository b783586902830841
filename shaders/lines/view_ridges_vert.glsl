// The vertex stage of view_ridges_geom.glsl: view_ridge_vertex.glsl per vertex.
out ViewRidgeVertexBlock {
    ViewRidgeVertex v;
} v_out;

void main() {
    v_out.v = view_ridge_vertex();
    gl_Position = u_mvp * vec4(a_position, 1.0);
}
