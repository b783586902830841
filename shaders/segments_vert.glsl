// Line segments made on the CPU (render/cpu_isolines.h), vertex stage: an
// end point in model coordinates with its opacity and occlusion tolerance.
layout(location = 0) in vec3 a_position;
layout(location = 1) in float a_alpha;
layout(location = 2) in float a_tolerance;  // model units
layout(location = 3) in float a_contour;    // 1: an occluding contour (exterior-only with --lines silhouette)

uniform mat4 u_mvp;

out SegmentVertex {
    float alpha;
    float tolerance;
    float contour;
} v_out;

void main() {
    v_out.alpha = a_alpha;
    v_out.tolerance = a_tolerance;
    v_out.contour = a_contour;
    gl_Position = u_mvp * vec4(a_position, 1.0);
}
