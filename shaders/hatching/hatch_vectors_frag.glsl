// Shader hatching's field pass, fragment stage: the visible surface's
// interpolated directions (hatch_vectors_vert.glsl) and its tone, where it
// faces the eye (0 elsewhere: no strokes on back faces seen through holes).
in HatchVectors {
    vec4 directions;
    float darkness;
    float facing;
} f_in;

layout(location = 0) out vec4 o_directions;
layout(location = 1) out float o_darkness;

void main() {
    bool front = f_in.facing > 0.0;
    o_directions = front ? f_in.directions : vec4(0.0);
    o_darkness = front ? f_in.darkness : 0.0;
}
