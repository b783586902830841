// Rectangles of the viewport, two triangles each, given in normalised
// device coordinates (the compositor's inked rectangles).
layout(location = 0) in vec2 a_ndc;

void main() { gl_Position = vec4(a_ndc, 0.0, 1.0); }
