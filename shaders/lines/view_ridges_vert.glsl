// Apparent ridges and principal highlights, vertex stage: per vertex, the
// view-dependent curvature and its derivative (view_curvature.glsl), and the
// quantities of the principal-highlight test (view_ridges_geom.glsl).
uniform mat4 u_mvp;
uniform vec3 u_eye;            // model coordinates
uniform float u_feature_size;  // fs
uniform int u_apparent_ridges; // 0: the view-dependent curvature is not needed

out ViewRidgeVertex {
    vec3 position;
    float view_curv;   // sqrt(q1) fs: the view-dependent curvature, dimensionless
    vec3 t1;           // its principal direction, model coordinates
    float dq1;         // D_t1 q1: zero on apparent ridges
    float kmax;        // the principal curvature of larger magnitude, signed: > 0 on ridges, < 0 in valleys
    vec3 dmax;         // its direction
    float v_dmax;      // v.dmax: zero where w lies along the other principal direction
    float ph_strength; // (kmax^2 - kmin^2) n.v fs^2, >= 0 where front-facing
    float unreliable;
    float facing;      // n.(eye - position): > 0 where turned towards the eye
} v_out;

void main() {
    vec3 to_eye = u_eye - a_position;
    vec3 v = normalize(to_eye);
    v_out.position = a_position;
    v_out.view_curv = 0.0;
    v_out.t1 = vec3(0.0);
    v_out.dq1 = 0.0;
    if (u_apparent_ridges != 0) {
        ViewCurvature vc = view_curvature(a_curv, a_dcurv, a_normal, a_d1, a_d2, to_eye);
        v_out.view_curv = sqrt(max(vc.q1, 0.0)) * u_feature_size;
        v_out.t1 = vc.t1.x * a_d1 + vc.t1.y * a_d2;
        v_out.dq1 = vc.dq1;
    }
    // rtsc's curv1 is the curvature of larger magnitude (trimesh2's order), not kappa's k1.
    bool first = abs(a_curv.x) >= abs(a_curv.y);
    v_out.kmax = first ? a_curv.x : a_curv.y;
    v_out.dmax = first ? a_d1 : a_d2;
    v_out.v_dmax = dot(v, v_out.dmax);
    float kmin = first ? a_curv.y : a_curv.x;
    v_out.ph_strength = (v_out.kmax * v_out.kmax - kmin * kmin) * dot(a_normal, v) * u_feature_size * u_feature_size;
    v_out.unreliable = a_unreliable;
    v_out.facing = dot(a_normal, to_eye);
    gl_Position = u_mvp * vec4(a_position, 1.0);
}
