// View-independent curvature lines, per vertex (the vertex stage,
// curvature_lines_vert.glsl, or a compute pass, triangles_comp.glsl): the
// fields whose zero sets are the lines (curvature_lines_geom.glsl).
uniform mat4 u_mvp;
uniform vec3 u_eye;  // model coordinates

struct CurvatureVertex {
    vec3 position;
    float gaussian;  // K = k1 k2: parabolic lines are its zeros
    float mean;      // H = (k1 + k2) / 2: the mean-zero lines are its zeros
    float kmax;      // the principal curvature of larger magnitude, signed
    float emax;      // its derivative along its own direction (C111 or C222)
    vec3 dmax;       // that direction (its sign is arbitrary per vertex)
    float unreliable;
    float facing;    // n.(eye - position): > 0 where turned towards the eye
};

CurvatureVertex curvature_vertex() {
    CurvatureVertex o;
    bool first = abs(a_curv.x) >= abs(a_curv.y);
    o.position = a_position;
    o.gaussian = a_curv.x * a_curv.y;
    o.mean = 0.5 * (a_curv.x + a_curv.y);
    o.kmax = first ? a_curv.x : a_curv.y;
    o.emax = first ? a_dcurv.x : a_dcurv.w;  // C(d1,d1,d1) = a, C(d2,d2,d2) = d
    o.dmax = first ? a_d1 : a_d2;
    o.unreliable = a_unreliable;
    o.facing = dot(a_normal, u_eye - a_position);
    return o;
}
