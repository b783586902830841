// View-independent curvature lines, per triangle:
//   parabolic:  K = 0;
//   mean-zero:  H = 0;
//   ridges and valleys (as rtsc; Ohtake et al. 2004): where the derivative
//   e of the larger-magnitude principal curvature kmax along its direction
//   crosses zero at a maximum of |kmax| (e falls along the direction where
//   kmax > 0: a ridge; rises where kmax < 0: a valley), kept where
//   |kmax| > threshold / fs, faded towards it with --fade. The principal
//   direction has no sign: the triangle's directions (and with them e, odd
//   in the direction) are turned to agree with its first vertex's.
// Hidden parts are removed by the same depth test as every line.
// As rtsc, a triangle turned away from the eye at all three corners (n.v <= 0
// with the fields' normals) draws nothing unless hidden lines are drawn.
CurvatureVertex tri[3];  // the triangle being cut

uniform int u_parabolic, u_mean_zero, u_ridges, u_valleys;
uniform float u_rv_threshold;  // dimensionless S
uniform float u_feature_size;  // fs
uniform int u_fade;            // fade ridges and valleys whose |kmax| is close to the threshold
uniform int u_hidden_lines;

vec4 clip_point(int i, int j, float s) { return mix(tri_clip[i], tri_clip[j], s); }

float tolerance() {
    return 0.5 * max(max(distance(tri[0].position, tri[1].position), distance(tri[1].position, tri[2].position)),
                     distance(tri[2].position, tri[0].position));
}

// The zero crossing of f on the triangle: two points as (edge start, edge end, parameter).
bool zero_segment(float f[3], out ivec2 e0, out float s0, out ivec2 e1, out float s1) {
    int n = 0;
    for (int i = 0; i < 3; ++i) {
        int j = (i + 1) % 3;
        if ((f[i] > 0.0) != (f[j] > 0.0)) {
            float s = f[i] / (f[i] - f[j]);
            if (n == 0) { e0 = ivec2(i, j); s0 = s; } else { e1 = ivec2(i, j); s1 = s; }
            ++n;
        }
    }
    return n == 2;
}

void draw_zero_set(float f[3]) {
    ivec2 e0, e1;
    float s0, s1;
    if (!zero_segment(f, e0, s0, e1, s1)) return;
    emit_segment(clip_point(e0.x, e0.y, s0), clip_point(e1.x, e1.y, s1), 1.0, 1.0, tolerance());
}

void ridges_and_valleys() {
    // Directions and derivatives turned to agree with vertex 0.
    float e[3];
    vec3 d = tri[0].dmax;
    e[0] = tri[0].emax;
    for (int i = 1; i < 3; ++i) {
        float flip = dot(tri[i].dmax, tri[0].dmax) < 0.0 ? -1.0 : 1.0;
        e[i] = flip * tri[i].emax;
        d += flip * tri[i].dmax;
    }
    ivec2 a0, a1;
    float s0, s1;
    if (!zero_segment(e, a0, s0, a1, s1)) return;
    // The gradient of e over the triangle (linear interpolation).
    vec3 p0 = tri[0].position, p1 = tri[1].position, p2 = tri[2].position;
    vec3 n = cross(p1 - p0, p2 - p0);
    float n2 = dot(n, n);
    if (n2 <= 0.0) return;
    vec3 grad = (e[0] * cross(n, p2 - p1) + e[1] * cross(n, p0 - p2) + e[2] * cross(n, p1 - p0)) / n2;
    float k = (tri[0].kmax + tri[1].kmax + tri[2].kmax) / 3.0;
    if (k * dot(grad, d) >= 0.0) return;  // a minimum of |kmax|, not a ridge or valley
    bool ridge = k > 0.0;
    if ((ridge && u_ridges == 0) || (!ridge && u_valleys == 0)) return;
    // Keep the part where |kmax| > threshold / fs (linear along the segment).
    float limit = u_rv_threshold / u_feature_size;
    float g0 = abs(mix(tri[a0.x].kmax, tri[a0.y].kmax, s0)) - limit;
    float g1 = abs(mix(tri[a1.x].kmax, tri[a1.y].kmax, s1)) - limit;
    if (g0 <= 0.0 && g1 <= 0.0) return;
    vec4 c0 = clip_point(a0.x, a0.y, s0), c1 = clip_point(a1.x, a1.y, s1);
    if (g0 <= 0.0) c0 = mix(c0, c1, g0 / (g0 - g1)), g0 = 0.0;
    else if (g1 <= 0.0) c1 = mix(c0, c1, g0 / (g0 - g1)), g1 = 0.0;
    // Fading as rtsc: opacity from 0 at the threshold to 1 at twice the threshold.
    float ramp = max(u_rv_threshold, 0.05) / u_feature_size;
    float alpha0 = u_fade != 0 ? clamp(g0 / ramp, 0.0, 1.0) : 1.0;
    float alpha1 = u_fade != 0 ? clamp(g1 / ramp, 0.0, 1.0) : 1.0;
    emit_segment(c0, c1, alpha0, alpha1, tolerance());
}

void extract_curvature_lines() {
    if (tri[0].unreliable + tri[1].unreliable + tri[2].unreliable > 0.0) return;
    if (u_hidden_lines == 0 && tri[0].facing <= 0.0 && tri[1].facing <= 0.0 && tri[2].facing <= 0.0) return;
    if (u_parabolic != 0) draw_zero_set(float[3](tri[0].gaussian, tri[1].gaussian, tri[2].gaussian));
    if (u_mean_zero != 0) draw_zero_set(float[3](tri[0].mean, tri[1].mean, tri[2].mean));
    if (u_ridges != 0 || u_valleys != 0) ridges_and_valleys();
}
