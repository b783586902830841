// Line passes: per-vertex view-dependent quantities (view_dependent.glsl)
// for the isoline extraction (isolines.glsl), computed from the attributes
// a_* by the vertex stage (lines_vert.glsl) or a compute pass
// (triangles_comp.glsl).
uniform mat4 u_mvp;
uniform vec3 u_eye;               // model coordinates
uniform float u_feature_size_sq;  // fs^2: Dw kr * fs^2 is dimensionless

struct LineVertex {
    vec3 position;      // model coordinates
    float ndotv;        // n.v with the normal of the curvature fields
    float contour_ndotv;  // n.v with the contour normal: occluding contours are its zeros
    float kr;           // kr sin^2(theta)
    float sc_strength;  // Dw kr * fs^2, compared with the dimensionless threshold
    float unreliable;
};

LineVertex line_vertex() {
    vec3 v = normalize(u_eye - a_position);
    ViewQuantities q = view_quantities(a_normal, a_d1, a_d2, a_curv, a_dcurv, v);
    LineVertex o;
    o.position = a_position;
    o.ndotv = q.ndotv;
    o.contour_ndotv = dot(a_fine_normal, v);
    o.kr = q.kr_sin2;
    o.sc_strength = q.dwkr * u_feature_size_sq;
    o.unreliable = a_unreliable;
    return o;
}
