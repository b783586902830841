// View-dependent curvature quantities (conventions.md, "View-dependent
// quantities"), evaluated per vertex every frame.
//   v: unit vector from the point to the eye, cos(theta) = n.v
//   (u, t) = (v.d1, v.d2), u^2 + t^2 = sin^2(theta), w = (u, t) / sin(theta)
struct ViewQuantities {
    float ndotv;    // cos(theta): occluding contours are its zeros
    float kr_sin2;  // kr sin^2(theta) = k1 u^2 + k2 t^2: the zeros of kr, but finite where
                    // sin(theta) -> 0 (looking straight at the surface), so it interpolates well
    float dwkr;     // Dw kr = C(w,w,w) - 2 tau^2 cot(theta), the tau form (equal to
                    // C(w,w,w) + 2 K cot(theta) on kr = 0, better behaved away from it)
};

ViewQuantities view_quantities(vec3 n, vec3 d1, vec3 d2, vec2 k, vec4 C, vec3 v) {
    ViewQuantities q;
    q.ndotv = dot(n, v);
    float u = dot(v, d1), t = dot(v, d2);
    float sin2 = max(u * u + t * t, 1e-12);
    q.kr_sin2 = k.x * u * u + k.y * t * t;
    float inv_sin = inversesqrt(sin2);
    float wu = u * inv_sin, wt = t * inv_sin;
    // C(w,w,w) = a w1^3 + 3 b w1^2 w2 + 3 c w1 w2^2 + d w2^3
    float cwww = wu * wu * (C.x * wu + 3.0 * C.y * wt) + wt * wt * (3.0 * C.z * wu + C.w * wt);
    // geodesic torsion along w: tau = (k2 - k1) u t / (u^2 + t^2)
    float tau = (k.y - k.x) * wu * wt;
    float cot_theta = q.ndotv * inv_sin;
    q.dwkr = cwww - 2.0 * tau * tau * cot_theta;
    return q;
}
