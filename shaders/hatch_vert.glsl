// Principal-direction hatching, vertex stage: one surface sample
// (geometry/surface_samples.h) per vertex, drawn as GL_POINTS; the geometry
// stage (hatch_geom.glsl) turns it into up to two strokes.
//
// Stroke density follows the tone: where the darkness (from the Lambertian
// tone) is t, the wanted number of strokes per pixel of screen is
// t / (spacing * length). Samples are uniform over the surface area A, in
// random order, so sample i is kept where the wanted number of strokes per
// unit of surface area, times A, exceeds i + 1/2: a kept sample stays on
// the same surface point from frame to frame (no "shower door" sliding),
// and zooming in or darkening only adds samples. The renderer draws the
// prefix of samples that can pass this test anywhere in the view.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;     // unit
layout(location = 2) in vec3 a_direction;  // d1, unit and tangent, zero where undefined

uniform mat4 u_mvp;
uniform vec3 u_eye;                // model coordinates
uniform mat3 u_normal_matrix;      // model -> camera, for the light
uniform vec3 u_light;              // towards the light, camera coordinates, unit
uniform vec2 u_viewport;           // pixels
uniform float u_pixels_per_unit;   // pixels per model unit at camera depth 1: P[1][1] * height / 2
uniform float u_strokes_per_area;  // A / (spacing * length): strokes per (pixel^2 / unit^2) of surface, times A
uniform float u_stroke_length;     // pixels
uniform int u_hatching;            // 1 min (along d2), 2 max (along d1), 3 cross

out HatchSample {
    vec4 first;       // clip-space offset from the centre to the end of each stroke; zero: no stroke
    vec4 second;
    float tolerance;  // occlusion tolerance, model units
} v_out;

uint hash_u32(uint x) {  // integer hash (Wellons' lowbias32)
    x ^= x >> 16; x *= 0x7feb352du;
    x ^= x >> 15; x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}
float random01(uint seed) { return float(hash_u32(seed) >> 8) * (1.0 / 16777216.0); }

// Half a stroke along the tangent d: the clip-space offset t * (MVP d) with
// t chosen so the stroke is u_stroke_length pixels long on screen. The
// stroke is the projection of a 3D tangent segment, so its depth follows
// the tangent plane. Zero where d is undefined or seen end-on.
vec4 half_stroke(vec4 clip, vec3 d, out float t) {
    t = 0.0;
    if (d == vec3(0.0)) return vec4(0.0);
    vec4 dc = u_mvp * vec4(d, 0.0);
    vec2 pixels_per_unit = (dc.xy - clip.xy * (dc.w / clip.w)) / clip.w * (0.5 * u_viewport);
    float speed = length(pixels_per_unit);
    if (speed < 1e-6) return vec4(0.0);
    t = 0.5 * u_stroke_length / speed;
    return t * dc;
}

void main() {
    vec4 clip = u_mvp * vec4(a_position, 1.0);
    gl_Position = clip;
    v_out.first = vec4(0.0);
    v_out.second = vec4(0.0);
    v_out.tolerance = 0.0;
    float cos_theta = dot(a_normal, normalize(u_eye - a_position));
    if (clip.w <= 0.0 || cos_theta <= 0.0) return;  // behind the eye, or back-facing

    float tone = max(dot(normalize(u_normal_matrix * a_normal), u_light), 0.0);
    float darkness = clamp((0.95 - tone) / 0.8, 0.0, 1.0);
    // Screen pixels per unit of surface area here: (pixels per unit)^2, foreshortened.
    float scale = u_pixels_per_unit / clip.w;
    float wanted = scale * scale * cos_theta * darkness * u_strokes_per_area;
    if (float(gl_VertexID) + 0.5 >= wanted) return;

    vec3 d2 = cross(a_normal, a_direction);
    float t1 = 0.0, t2 = 0.0;
    v_out.first = half_stroke(clip, u_hatching == 1 ? d2 : a_direction, t1);
    // Cross-hatching: a second stroke across the first in the darker tones.
    if (u_hatching == 3 && random01(uint(gl_VertexID)) < (darkness - 0.4) / 0.6)
        v_out.second = half_stroke(clip, d2, t2);
    // The surface may bend away from the straight stroke by about its own
    // half-length before it should hide it.
    v_out.tolerance = 0.5 * max(t1, t2);
}
