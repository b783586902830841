// Line passes, vertex stage: per-vertex view-dependent quantities for the
// geometry shader that extracts zero crossings (isolines_geom.glsl).
uniform mat4 u_mvp;
uniform vec3 u_eye;               // model coordinates
uniform float u_feature_size_sq;  // fs^2: Dw kr * fs^2 is dimensionless

out LineVertex {
    vec3 position;      // model coordinates
    float ndotv;        // n.v with the normal of the curvature fields
    float contour_ndotv;  // n.v with the contour normal: occluding contours are its zeros
    float kr;           // kr sin^2(theta)
    float sc_strength;  // Dw kr * fs^2, compared with the dimensionless threshold
    float unreliable;
    flat int id;        // vertex index: fixes the order in which shared edges are cut
} v_out;

void main() {
    vec3 v = normalize(u_eye - a_position);
    ViewQuantities q = view_quantities(a_normal, a_d1, a_d2, a_curv, a_dcurv, v);
    v_out.position = a_position;
    v_out.ndotv = q.ndotv;
    v_out.contour_ndotv = dot(a_fine_normal, v);
    v_out.kr = q.kr_sin2;
    v_out.sc_strength = q.dwkr * u_feature_size_sq;
    v_out.unreliable = a_unreliable;
    v_out.id = gl_VertexID;
    gl_Position = u_mvp * vec4(a_position, 1.0);
}
