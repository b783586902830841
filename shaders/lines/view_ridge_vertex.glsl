// Apparent ridges and principal highlights, per vertex (the vertex stage,
// view_ridges_vert.glsl, or a compute pass, triangles_comp.glsl): per vertex,
// the view-dependent curvature and its derivative (view_curvature.glsl), and
// the quantities of the principal-highlight test (view_ridges_geom.glsl).
uniform mat4 u_mvp;
uniform vec3 u_eye;            // model coordinates
uniform float u_feature_size;  // fs
uniform int u_apparent_ridges; // 0: the view-dependent curvature is not needed

struct ViewRidgeVertex {
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
};

ViewRidgeVertex view_ridge_vertex() {
    ViewRidgeVertex o;
    vec3 to_eye = u_eye - a_position;
    vec3 v = normalize(to_eye);
    o.position = a_position;
    o.view_curv = 0.0;
    o.t1 = vec3(0.0);
    o.dq1 = 0.0;
    if (u_apparent_ridges != 0) {
        ViewCurvature vc = view_curvature(a_curv, a_dcurv, a_normal, a_d1, a_d2, to_eye);
        o.view_curv = sqrt(max(vc.q1, 0.0)) * u_feature_size;
        o.t1 = vc.t1.x * a_d1 + vc.t1.y * a_d2;
        o.dq1 = vc.dq1;
    }
    // rtsc's curv1 is the curvature of larger magnitude (trimesh2's order), not kappa's k1.
    bool first = abs(a_curv.x) >= abs(a_curv.y);
    o.kmax = first ? a_curv.x : a_curv.y;
    o.dmax = first ? a_d1 : a_d2;
    o.v_dmax = dot(v, o.dmax);
    float kmin = first ? a_curv.y : a_curv.x;
    o.ph_strength = (o.kmax * o.kmax - kmin * kmin) * dot(a_normal, v) * u_feature_size * u_feature_size;
    o.unreliable = a_unreliable;
    o.facing = dot(a_normal, to_eye);
    return o;
}
