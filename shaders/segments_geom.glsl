// Line segments made on the CPU, geometry stage: each (GL_LINES) becomes a
// quad of the line width (line_quad.glsl), tested for occlusion in
// lines_frag.glsl like the segments isolines_geom.glsl makes on the GPU.
layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;

in SegmentVertex {
    float alpha;
    float tolerance;
    float kind;
} v_in[];

uniform float u_scale_tolerance;  // detail (px) x pixel size per unit of camera distance; 0 without detail
uniform int u_silhouette_only;    // contours only where they border the background

void main() {
    float w = max(gl_in[0].gl_Position.w, gl_in[1].gl_Position.w);
    exterior_only_ = v_in[0].kind > 1.5 && u_silhouette_only != 0 ? 1.0 : 0.0;
    float scale = v_in[0].kind > 0.5 ? u_scale_tolerance * w : 0.0;
    emit_segment(gl_in[0].gl_Position, gl_in[1].gl_Position, v_in[0].alpha, v_in[1].alpha,
                 max(v_in[0].tolerance, scale));
}
