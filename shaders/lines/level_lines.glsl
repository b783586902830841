// Level lines: per triangle, the segments where the linearly
// interpolated value crosses each of the levels first + k step, k = 0 ..
// count - 1 (at most 16): isophotes (n.l levels) or topographic lines
// (height levels along y). Hidden parts are removed like every line's.
// As rtsc, a triangle turned away from the eye at all three corners (n.v <= 0
// with the fields' normals) draws nothing unless hidden lines are drawn.
LevelVertex tri[3];  // the triangle being cut

uniform float u_first, u_step;
uniform int u_count;
uniform int u_hidden_lines;

void extract_level_lines() {
    if (u_hidden_lines == 0 && tri[0].facing <= 0.0 && tri[1].facing <= 0.0 && tri[2].facing <= 0.0) return;
    float lo = min(min(tri[0].value, tri[1].value), tri[2].value);
    float hi = max(max(tri[0].value, tri[1].value), tri[2].value);
    float tolerance = 0.5 * max(max(distance(tri[0].position, tri[1].position),
                                    distance(tri[1].position, tri[2].position)),
                                distance(tri[2].position, tri[0].position));
    int k0 = max(0, int(ceil((lo - u_first) / u_step)));
    int k1 = min(u_count - 1, int(floor((hi - u_first) / u_step)));
    for (int k = k0; k <= k1 && k < k0 + 16; ++k) {
        float level = u_first + float(k) * u_step;
        vec4 p[2];
        int n = 0;
        for (int i = 0; i < 3; ++i) {
            int j = (i + 1) % 3;
            float a = tri[i].value - level, b = tri[j].value - level;
            if ((a > 0.0) != (b > 0.0) && n < 2) {
                p[n++] = mix(tri_clip[i], tri_clip[j], a / (a - b));
            }
        }
        if (n == 2) emit_segment(p[0], p[1], 1.0, 1.0, tolerance);
    }
}
