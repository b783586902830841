// Level lines, geometry stage: per triangle, the segments where the linearly
// interpolated value crosses each of the levels first + k step, k = 0 ..
// count - 1 (at most 16): isophotes (n.l levels) or topographic lines
// (height levels along y). Hidden parts are removed like every line's.
// As rtsc, a triangle turned away from the eye at all three corners (n.v <= 0
// with the fields' normals) draws nothing unless hidden lines are drawn.
layout(triangles) in;
layout(triangle_strip, max_vertices = 64) out;

in LevelVertex {
    vec3 position;
    float value;
    float facing;
} v_in[];

uniform float u_first, u_step;
uniform int u_count;
uniform int u_hidden_lines;

void main() {
    if (u_hidden_lines == 0 && v_in[0].facing <= 0.0 && v_in[1].facing <= 0.0 && v_in[2].facing <= 0.0) return;
    float lo = min(min(v_in[0].value, v_in[1].value), v_in[2].value);
    float hi = max(max(v_in[0].value, v_in[1].value), v_in[2].value);
    float tolerance = 0.5 * max(max(distance(v_in[0].position, v_in[1].position),
                                    distance(v_in[1].position, v_in[2].position)),
                                distance(v_in[2].position, v_in[0].position));
    int k0 = max(0, int(ceil((lo - u_first) / u_step)));
    int k1 = min(u_count - 1, int(floor((hi - u_first) / u_step)));
    for (int k = k0; k <= k1 && k < k0 + 16; ++k) {
        float level = u_first + float(k) * u_step;
        vec4 p[2];
        int n = 0;
        for (int i = 0; i < 3; ++i) {
            int j = (i + 1) % 3;
            float a = v_in[i].value - level, b = v_in[j].value - level;
            if ((a > 0.0) != (b > 0.0) && n < 2) {
                p[n++] = mix(gl_in[i].gl_Position, gl_in[j].gl_Position, a / (a - b));
            }
        }
        if (n == 2) emit_segment(p[0], p[1], 1.0, 1.0, tolerance);
    }
}
