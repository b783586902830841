// Line segments made on the CPU (render/cpu_lines.h), vertex stage: an
// end point in model coordinates with its opacity and occlusion tolerance.
layout(location = 0) in vec3 a_position;
layout(location = 1) in float a_alpha;
layout(location = 2) in float a_tolerance;  // model units
layout(location = 3) in float a_kind;  // 0: a line; 1: a zero set of a view-dependent field (isolines_geom.glsl's
                                       // kinds, which may lie the detail scale behind); 2: an occluding contour

uniform mat4 u_mvp;

out SegmentVertex {
    float alpha;
    float tolerance;
    float kind;
} v_out;

void main() {
    v_out.alpha = a_alpha;
    v_out.tolerance = a_tolerance;
    v_out.kind = a_kind;
    gl_Position = u_mvp * vec4(a_position, 1.0);
}
