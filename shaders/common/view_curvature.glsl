// View-dependent curvature (Judd, Durand and Adelson 2007, "Apparent ridges
// for line drawing", Sec. 3): the curvature of the surface as seen on the
// screen, Q = S P^-1 = S (I + (sec(theta) - 1) w w^T) in the principal frame
// (d1, d2), S = diag(k1, k2), w the unit projected view direction. Its
// principal value q1 is the largest eigenvalue of Q^T Q (a squared
// curvature, as rtsc computes it) with unit eigenvector t1.
//
// Its derivative along t1 is computed here from the fields, not from
// neighbouring vertices: with every quantity a tensor of the tangent plane
// and D its covariant derivative along a unit tangent x,
//   D S  = C(x, ., .)                              (the paper's C)
//   D n  = S x,  D v = -(x - (x.v) v) / r          (r: distance to the eye)
//   D cos(theta) = vt.(S x) + cos(theta) (vt.x) / r,  vt = v - cos(theta) n
//   D vt = -(x - (x.vt) vt) / r - cos(theta) S x
//   D w  = (D vt - w (w.D vt)) / |vt|
// and for the largest eigenvalue of a symmetric matrix, D q1 = t1^T D(Q^T Q) t1
// = 2 (Q t1).(D Q t1). As rtsc, the derivative is per unit of projected
// length: divided by |cos(theta)|.
struct ViewCurvature {
    float q1;   // squared view-dependent curvature (largest eigenvalue of Q^T Q)
    vec2 t1;    // its direction in the (d1, d2) frame, unit
    float dq1;  // D_t1 q1 per unit of projected length
};

ViewCurvature view_curvature(vec2 k, vec4 C, vec3 n, vec3 d1, vec3 d2, vec3 to_eye) {
    float r = max(length(to_eye), 1e-20);
    vec3 v = to_eye / r;
    float c = dot(n, v);
    float abs_c = max(abs(c), 1e-4);
    vec2 vt = vec2(dot(v, d1), dot(v, d2));
    float s = max(length(vt), 1e-6);
    vec2 w = vt / s;
    float sec_minus_1 = 1.0 / abs_c - 1.0;
    mat2 S = mat2(k.x, 0.0, 0.0, k.y);
    mat2 M = mat2(1.0) + sec_minus_1 * outerProduct(w, w);
    mat2 Q = S * M;
    mat2 A = transpose(Q) * Q;
    // Largest eigenvalue of the symmetric A and its eigenvector.
    float mean = 0.5 * (A[0][0] + A[1][1]);
    float radius = sqrt(A[1][0] * A[1][0] + 0.25 * (A[1][1] - A[0][0]) * (A[1][1] - A[0][0]));
    ViewCurvature vc;
    vc.q1 = mean + radius;
    vec2 e = vec2(A[1][1] - vc.q1, -A[1][0]);  // (A - q1 I) e = 0, from the first row...
    vec2 e2 = vec2(-A[1][0], A[0][0] - vc.q1); // ...or the second, whichever is better conditioned
    e = dot(e, e) >= dot(e2, e2) ? e : e2;
    vc.t1 = dot(e, e) > 1e-30 ? normalize(e) : vec2(1.0, 0.0);

    vec2 x = vc.t1;
    vec2 Sx = S * x;
    float dc = sign(c) * (dot(vt, Sx) + c * dot(vt, x) / r);  // derivative of |cos(theta)|
    float dsec = -dc / (abs_c * abs_c);
    vec2 dvt = -(x - dot(x, vt) * vt) / r - c * Sx;
    vec2 dw = (dvt - w * dot(w, dvt)) / s;
    mat2 dM = dsec * outerProduct(w, w) + sec_minus_1 * (outerProduct(dw, w) + outerProduct(w, dw));
    // C(x, ., .): C111 = a, C112 = b, C122 = c, C222 = d.
    mat2 dS = mat2(C.x * x.x + C.y * x.y, C.y * x.x + C.z * x.y,
                   C.y * x.x + C.z * x.y, C.z * x.x + C.w * x.y);
    mat2 dQ = dS * M + S * dM;
    vc.dq1 = 2.0 * dot(Q * x, dQ * x) / abs_c;
    return vc;
}
