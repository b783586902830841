// Per-vertex attributes uploaded once by render/fields/mesh_buffers.cpp.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;   // unit, outward
layout(location = 2) in vec3 a_d1;       // principal direction of k1
layout(location = 3) in vec3 a_d2;       // principal direction of k2 (d1 x d2 = n)
layout(location = 4) in vec2 a_curv;     // (k1, k2), k1 >= k2
layout(location = 5) in vec4 a_dcurv;    // C = (a, b, c, d) = (C111, C112, C122, C222) in the (d1, d2) frame
layout(location = 6) in float a_unreliable;  // 1 where geometry/vertex_flags.h marks the estimate unreliable
layout(location = 7) in vec3 a_fine_normal;  // the normal at pixel scale, for occluding contours and shading
                                             // (with --detail the fields' own normal is at the detail scale)
