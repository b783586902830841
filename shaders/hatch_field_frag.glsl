// Hatching field pass, fragment stage: (cos 2a, sin 2a) * reliability of the
// direction's window angle a (doubled, so that d and -d agree and the field
// can be averaged), the darkness, and 1 where the surface faces the eye.
in HatchVertex {
    vec2 direction;
    float reliability;
    float darkness;
    float facing;
} f_in;

out vec4 o_field;

void main() {
    float len = length(f_in.direction);
    vec2 d = len > 1e-12 ? f_in.direction / len : vec2(1.0, 0.0);
    float w = len > 1e-12 ? f_in.reliability : 0.0;
    o_field = vec4(vec2(d.x * d.x - d.y * d.y, 2.0 * d.x * d.y) * w, f_in.darkness, f_in.facing > 0.0 ? 1.0 : 0.0);
}
