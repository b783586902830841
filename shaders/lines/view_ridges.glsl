// Apparent ridges and principal highlights, per triangle; as
// rtsc, each is a line through the triangle where a direction field weighted
// by a derivative changes sign along edges (the direction has no sign per
// vertex; the product does), kept where a strength exceeds its threshold.
//   apparent ridges (Judd, Durand and Adelson 2007): tmax = D_t1 q1 t1 on
//     the view-dependent curvature q1 (view_curvature.glsl); a maximum when
//     the tmax on both sides point towards the line; kept where the
//     view-dependent curvature sqrt(q1) > threshold / fs. Near contours
//     q1 grows without bound: there they follow the contour, as in the paper.
//   principal highlights (DeCarlo and Rusinkiewicz 2007): v.dmax = 0 (the
//     projected view direction along the principal direction of smaller
//     curvature) where kmax, the curvature of larger magnitude (rtsc's
//     curv1), is >= 0 at all three vertices (ridge kind) or <= 0 (valley
//     kind), dmax turned to agree with the vertex of largest |kmax| (none if
//     one is more than 45 degrees away), kept where
//     (kmax^2 - kmin^2) n.v > threshold / fs^2.
// Fading (--fade): opacity from 0 at the threshold to 1 at twice the
// threshold, as the suggestive contours'.
ViewRidgeVertex tri[3];  // the triangle being cut

uniform int u_principal_highlights, u_fade;  // u_apparent_ridges: view_ridge_vertex.glsl
uniform float u_ar_threshold;  // dimensionless, on sqrt(q1) fs
uniform float u_ph_threshold;  // dimensionless, on (kmax^2 - kmin^2) n.v fs^2
uniform int u_hidden_lines;

float tolerance() {
    return 0.5 * max(max(distance(tri[0].position, tri[1].position), distance(tri[1].position, tri[2].position)),
                     distance(tri[2].position, tri[0].position));
}

// Where on edge (i, j) a quantity of opposite signs at i and j crosses zero (from i).
float edge_param(float fi, float fj) { return abs(fi) / max(abs(fi) + abs(fj), 1e-30); }

vec3 point_on(int i, int j, float s) { return mix(tri[i].position, tri[j].position, s); }
vec4 clip_on(int i, int j, float s) { return mix(tri_clip[i], tri_clip[j], s); }

// The segment c0 -> c1 where the linear strength g (g0, g1 at the ends) is positive, faded.
void emit_above(vec4 c0, vec4 c1, float g0, float g1, float threshold) {
    if (g0 <= 0.0 && g1 <= 0.0) return;
    if (g0 <= 0.0) {
        c0 = mix(c0, c1, g0 / (g0 - g1));
        g0 = 0.0;
    } else if (g1 <= 0.0) {
        c1 = mix(c0, c1, g0 / (g0 - g1));
        g1 = 0.0;
    }
    float a0 = 1.0, a1 = 1.0;
    if (u_fade != 0) {
        float ramp = max(threshold, 0.05);
        a0 = clamp(g0 / ramp, 0.0, 1.0);
        a1 = clamp(g1 / ramp, 0.0, 1.0);
    }
    emit_segment(c0, c1, a0, a1, tolerance());
}

// The vertex shared by the two edges (k, k+1) that are crossed, when exactly two are.
int lone_vertex(bvec3 crossed) { return !crossed.x ? 2 : (!crossed.y ? 0 : 1); }

void apparent_ridges() {
    float q[3] = float[3](tri[0].view_curv, tri[1].view_curv, tri[2].view_curv);
    if (q[0] <= u_ar_threshold && q[1] <= u_ar_threshold && q[2] <= u_ar_threshold) return;
    vec3 tm[3];
    float e[3];
    for (int i = 0; i < 3; ++i) {
        e[i] = tri[i].dq1;
        tm[i] = e[i] * tri[i].t1;  // points to where q1 grows
    }
    bvec3 crossed = bvec3(dot(tm[0], tm[1]) <= 0.0, dot(tm[1], tm[2]) <= 0.0, dot(tm[2], tm[0]) <= 0.0);
    int n = int(crossed.x) + int(crossed.y) + int(crossed.z);
    if (n < 2) return;
    vec3 normal = cross(tri[1].position - tri[0].position, tri[2].position - tri[0].position);
    if (n == 2) {
        int l = lone_vertex(crossed), a = (l + 1) % 3, b = (l + 2) % 3;
        float sa = edge_param(e[l], e[a]), sb = edge_param(e[l], e[b]);
        vec3 pa = point_on(l, a, sa), pb = point_on(l, b, sb);
        // A maximum: tmax on both sides of the line point towards it (Judd et al., Fig. 6).
        vec3 perp = cross(normal, pa - pb);
        float side = dot(tri[l].position - pa, perp);
        if (dot(tm[l], perp) * side >= 0.0 || dot(tm[a], perp) * side <= 0.0 || dot(tm[b], perp) * side <= 0.0)
            return;
        emit_above(clip_on(l, a, sa), clip_on(l, b, sb), mix(q[l], q[a], sa) - u_ar_threshold,
                   mix(q[l], q[b], sb) - u_ar_threshold, u_ar_threshold);
        return;
    }
    // Crossings on all three edges: each joined to the centre.
    vec3 centre = (tri[0].position + tri[1].position + tri[2].position) / 3.0;
    vec4 clip_centre = (tri_clip[0] + tri_clip[1] + tri_clip[2]) / 3.0;
    float q_centre = (q[0] + q[1] + q[2]) / 3.0;
    for (int i = 0; i < 3; ++i) {
        int j = (i + 1) % 3;
        float s = edge_param(e[i], e[j]);
        vec3 perp = cross(normal, point_on(i, j, s) - centre);
        if (dot(tm[i], perp) * dot(tri[i].position - centre, perp) >= 0.0 ||
            dot(tm[j], perp) * dot(tri[j].position - centre, perp) >= 0.0)
            continue;
        emit_above(clip_on(i, j, s), clip_centre, mix(q[i], q[j], s) - u_ar_threshold, q_centre - u_ar_threshold,
                   u_ar_threshold);
    }
}

void principal_highlights() {
    float lowest = min(min(tri[0].kmax, tri[1].kmax), tri[2].kmax);
    float highest = max(max(tri[0].kmax, tri[1].kmax), tri[2].kmax);
    if (lowest < 0.0 && highest > 0.0) return;  // neither a ridge nor a valley kind
    int ref = 0;
    for (int i = 1; i < 3; ++i)
        if (abs(tri[i].kmax) > abs(tri[ref].kmax)) ref = i;
    float f[3];
    for (int i = 0; i < 3; ++i) {
        float flip = dot(tri[i].dmax, tri[ref].dmax) < 0.0 ? -1.0 : 1.0;
        if (flip * dot(tri[i].dmax, tri[ref].dmax) < 0.70710678) return;  // dmax turns too fast to follow
        f[i] = flip * tri[i].v_dmax;
    }
    // Values are classified as > 0 or not, so there are 0 or 2 crossings, also
    // where vertices lie exactly on the line (rtsc's f_i f_j <= 0 finds three
    // there and draws nothing: dashes along symmetry planes).
    bvec3 pos = bvec3(f[0] > 0.0, f[1] > 0.0, f[2] > 0.0);
    bvec3 crossed = bvec3(pos.x != pos.y, pos.y != pos.z, pos.z != pos.x);
    if (!any(crossed)) return;
    int l = lone_vertex(crossed), a = (l + 1) % 3, b = (l + 2) % 3;
    float sa = edge_param(f[l], f[a]), sb = edge_param(f[l], f[b]);
    float ga = abs(mix(tri[l].ph_strength, tri[a].ph_strength, sa)) - u_ph_threshold;
    float gb = abs(mix(tri[l].ph_strength, tri[b].ph_strength, sb)) - u_ph_threshold;
    emit_above(clip_on(l, a, sa), clip_on(l, b, sb), ga, gb, u_ph_threshold);
}

void extract_view_ridges() {
    if (tri[0].unreliable + tri[1].unreliable + tri[2].unreliable > 0.0) return;
    // As rtsc, nothing on a triangle turned away at all three corners unless hidden lines are drawn.
    if (u_hidden_lines == 0 && tri[0].facing <= 0.0 && tri[1].facing <= 0.0 && tri[2].facing <= 0.0) return;
    if (u_apparent_ridges != 0) apparent_ridges();
    if (u_principal_highlights != 0) principal_highlights();
}
