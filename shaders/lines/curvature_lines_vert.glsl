// View-independent curvature lines, vertex stage: the fields whose zero sets
// are the lines (curvature_lines_geom.glsl).
uniform mat4 u_mvp;
uniform vec3 u_eye;  // model coordinates

out CurvatureVertex {
    vec3 position;
    float gaussian;  // K = k1 k2: parabolic lines are its zeros
    float mean;      // H = (k1 + k2) / 2: the mean-zero lines are its zeros
    float kmax;      // the principal curvature of larger magnitude, signed
    float emax;      // its derivative along its own direction (C111 or C222)
    vec3 dmax;       // that direction (its sign is arbitrary per vertex)
    float unreliable;
    float facing;    // n.(eye - position): > 0 where turned towards the eye
} v_out;

void main() {
    bool first = abs(a_curv.x) >= abs(a_curv.y);
    v_out.position = a_position;
    v_out.gaussian = a_curv.x * a_curv.y;
    v_out.mean = 0.5 * (a_curv.x + a_curv.y);
    v_out.kmax = first ? a_curv.x : a_curv.y;
    v_out.emax = first ? a_dcurv.x : a_dcurv.w;  // C(d1,d1,d1) = a, C(d2,d2,d2) = d
    v_out.dmax = first ? a_d1 : a_d2;
    v_out.unreliable = a_unreliable;
    v_out.facing = dot(a_normal, u_eye - a_position);
    gl_Position = u_mvp * vec4(a_position, 1.0);
}
