// Hatching field pass, fragment stage, in 8 bits a channel (fast to read
// back; the directions are averaged over many pixels afterwards):
//   r, g: the window angles of d1 and d2, in [0, pi) mapped to [0, 1)
//   b:    their reliability
//   a:    0 where the surface faces away, else the darkness mapped to [1/255, 1]
in HatchVertex {
    vec2 direction1;
    vec2 direction2;
    float reliability;
    float darkness;
    float facing;
} f_in;

out vec4 o_field;

const float PI = 3.14159265358979;

float angle(vec2 d) {  // in [0, 1): the direction's angle over pi (d and -d agree)
    float a = atan(d.y, d.x);
    return fract((a < 0.0 ? a + PI : a) / PI);
}

void main() {
    float defined = min(length(f_in.direction1), length(f_in.direction2)) > 1e-12 ? 1.0 : 0.0;
    float a = f_in.facing > 0.0 ? (1.0 + 254.0 * f_in.darkness) / 255.0 : 0.0;
    o_field = vec4(angle(f_in.direction1), angle(f_in.direction2), f_in.reliability * defined, a);
}
