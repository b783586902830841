// Apparent ridges and principal highlights, vertex stage: per vertex, the
// view-dependent curvature and its derivative (view_curvature.glsl), and the
// quantities of the principal-highlight test (view_ridges_geom.glsl).
uniform mat4 u_mvp;
uniform vec3 u_eye;            // model coordinates
uniform float u_feature_size;  // fs

out ViewRidgeVertex {
    vec3 position;
    float view_curv;   // sqrt(q1) fs: the view-dependent curvature, dimensionless
    vec3 t1;           // its principal direction, model coordinates
    float dq1;         // D_t1 q1: zero on apparent ridges
    float k1;          // signed larger principal curvature: > 0 on ridges, < 0 in valleys
    vec3 d1;           // its direction
    float v_d1;        // v.d1: zero where w lies along d2
    float ph_strength; // (k1^2 - k2^2) n.v fs^2
    float unreliable;
} v_out;

void main() {
    vec3 to_eye = u_eye - a_position;
    ViewCurvature vc = view_curvature(a_curv, a_dcurv, a_normal, a_d1, a_d2, to_eye);
    vec3 v = normalize(to_eye);
    v_out.position = a_position;
    v_out.view_curv = sqrt(max(vc.q1, 0.0)) * u_feature_size;
    v_out.t1 = vc.t1.x * a_d1 + vc.t1.y * a_d2;
    v_out.dq1 = vc.dq1;
    v_out.k1 = a_curv.x;
    v_out.d1 = a_d1;
    v_out.v_d1 = dot(v, a_d1);
    v_out.ph_strength = (a_curv.x * a_curv.x - a_curv.y * a_curv.y) * dot(a_normal, v) * u_feature_size * u_feature_size;
    v_out.unreliable = a_unreliable;
    gl_Position = u_mvp * vec4(a_position, 1.0);
}
