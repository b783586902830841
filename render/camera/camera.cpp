#include "render/camera/camera.h"

#include "geometry/mesh/position_bounds.h"
#include "geometry/parallel/double_lanes.h"
#include "geometry/parallel/parallel.h"
#include "geometry/view/default_view.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace kappa::render {

BoundingSphere bounding_sphere(const Mesh& mesh) { return bounding_sphere(mesh, position_bounds(mesh.positions)); }

namespace {

using lanes::Doubles2;

// The largest squared distance from c of points [first, last), in double (squares of coordinates near
// 1e20 overflow float) as glm::dot(d, d) takes it, (x^2 + y^2) + z^2, so the same bits one point at a
// time or two at a time in lanes. A NaN distance is passed over, as std::max passes it over.
double largest_square(const glm::vec3* p, size_t first, size_t last, glm::dvec3 c) {
    double largest = 0;
    size_t v = first;
    if (last - first >= 4) {
        // Four points, twelve floats, as six pairs: (x0 y0) (z0 x1) (y1 z1) (x2 y2) (z2 x3) (y3 z3).
        const Doubles2 cxy{c.x, c.y}, czx{c.z, c.x}, cyz{c.y, c.z};
        auto low = [](lanes::Lanes x) { return __builtin_convertvector(__builtin_shufflevector(x, x, 0, 1), Doubles2); };
        auto high = [](lanes::Lanes x) { return __builtin_convertvector(__builtin_shufflevector(x, x, 2, 3), Doubles2); };
        Doubles2 most{};
        for (; v + 4 <= last; v += 4) {
            lanes::Lanes f[3];
            std::memcpy(f, &p[v], sizeof f);
            const Doubles2 a = low(f[0]) - cxy, b = high(f[0]) - czx, d = low(f[1]) - cyz;
            const Doubles2 e = high(f[1]) - cxy, g = low(f[2]) - czx, h = high(f[2]) - cyz;
            const Doubles2 aa = a * a, bb = b * b, dd = d * d, ee = e * e, gg = g * g, hh = h * h;
            // Points 0 and 1: x from (aa, bb), y from (aa, dd), z from (bb, dd); points 2 and 3 likewise.
            const Doubles2 r01 = (__builtin_shufflevector(aa, bb, 0, 3) + __builtin_shufflevector(aa, dd, 1, 2)) +
                                 __builtin_shufflevector(bb, dd, 0, 3);
            const Doubles2 r23 = (__builtin_shufflevector(ee, gg, 0, 3) + __builtin_shufflevector(ee, hh, 1, 2)) +
                                 __builtin_shufflevector(gg, hh, 0, 3);
            most = most < r01 ? r01 : most;
            most = most < r23 ? r23 : most;
        }
        largest = std::max(most[0], most[1]);
    }
    for (; v < last; ++v) {
        const glm::dvec3 d = glm::dvec3(p[v]) - c;
        largest = std::max(largest, glm::dot(d, d));
    }
    return largest;
}

}  // namespace

BoundingSphere bounding_sphere(const Mesh& mesh, const PositionBounds& box) {
    if (mesh.positions.empty() || box.empty()) return {};
    // The radius in blocks, in parallel: the largest is the same in any order.
    constexpr size_t kBlock = 65536;
    const size_t n = mesh.positions.size(), blocks = (n + kBlock - 1) / kBlock;
    BoundingSphere s;
    s.center = box.center();
    std::vector<double> r2(blocks, 0.0);
    parallel_for_chunked(blocks, [&](size_t b) {
        r2[b] = largest_square(mesh.positions.data(), b * kBlock, std::min(n, (b + 1) * kBlock), glm::dvec3(s.center));
    }, 1);
    const double largest = *std::max_element(r2.begin(), r2.end());
    s.radius = largest > 0 ? float(std::sqrt(largest)) : 1.0f;
    return s;
}

Camera Camera::look_at(glm::vec3 eye, glm::vec3 target, glm::vec3 up, float fov_y_deg) {
    Camera c;
    c.view = glm::lookAt(eye, target, up);
    c.fov_y_deg = fov_y_deg;
    return c;
}

Camera Camera::framing(const BoundingSphere& sphere, float fov_y_deg, float aspect, glm::vec3 direction,
                       glm::vec3 up_axis) {
    // The sphere touches the narrower side of the frustum: distance r / sin(half angle).
    const float half_y = glm::radians(fov_y_deg) * 0.5f;
    const float half_x = std::atan(std::tan(half_y) * aspect);
    const float distance = sphere.radius / std::sin(std::min(half_x, half_y));
    const float len = glm::length(direction);
    const glm::vec3 d = len > 0 && std::isfinite(len) ? direction / len : glm::vec3(0, 0, 1);
    const ViewFrame frame = view_frame(up_axis);
    glm::vec3 up;
    if (frame.up == glm::vec3(0, 1, 0)) {
        // y up, unless looking along y: then -z up (the top view's "north").
        up = std::fabs(d.y) > 0.999f ? glm::vec3(0, 0, -d.y) : glm::vec3(0, 1, 0);
    } else {
        // The same about another up: looking along it, the frame's front down.
        const float along = glm::dot(d, frame.up);
        up = std::fabs(along) > 0.999f ? -along * frame.front : frame.up;
    }
    return look_at(sphere.center + distance * d, sphere.center, up, fov_y_deg);
}

Camera Camera::default_view(const Mesh& mesh, const BoundingSphere& sphere, float fov_y_deg, float aspect,
                            std::optional<glm::vec3> up) {
    const DefaultView v = kappa::default_view(mesh, up);
    return framing(sphere, fov_y_deg, aspect, v.eye, v.up);
}

glm::vec3 Camera::eye() const { return glm::vec3(glm::inverse(view)[3]); }

glm::mat4 Camera::projection(const BoundingSphere& sphere, float aspect) const {
    // Depth range of the sphere in front of the camera, with some slack.
    const float center_depth = -(view * glm::vec4(sphere.center, 1)).z;
    // The model-view may scale (.xf files): measure the radius in camera units.
    const float scale = glm::length(glm::vec3(view[0]));
    const float r = sphere.radius * (scale > 0 ? scale : 1.0f);
    const float far_plane = std::max(center_depth + 1.01f * r, 1e-3f * r);
    const float near_plane = std::max(center_depth - 1.01f * r, far_plane * 1e-4f);
    return glm::perspective(glm::radians(fov_y_deg), aspect, near_plane, far_plane);
}

Camera Camera::orbited(glm::vec3 center, glm::vec3 axis, float radians) const {
    // Rotating the camera by +a around the axis = rotating the model by -a.
    const glm::mat4 to_center = glm::translate(glm::mat4(1), center);
    const glm::mat4 rotate = glm::rotate(glm::mat4(1), -radians, glm::normalize(axis));
    Camera c = *this;
    c.view = view * to_center * rotate * glm::translate(glm::mat4(1), -center);
    return c;
}

float rtsc_fov_y_deg(int width, int height) {
    const float diagonal = std::sqrt(float(width) * float(width) + float(height) * float(height));
    return glm::degrees(2.0f * std::atan(0.35f * float(height) / diagonal));
}

glm::mat4 read_xf(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error(path + ": cannot open the viewpoint file");
    std::vector<double> v;
    std::string token;
    while (in >> token) {
        std::istringstream ss(token);
        double x;
        if (!(ss >> x) || !ss.eof() || !std::isfinite(x))
            throw std::runtime_error(path + ": not a .xf viewpoint file ('" + token + "' is not a number)");
        v.push_back(x);
    }
    if (v.size() != 12 && v.size() != 16)
        throw std::runtime_error(path + ": a .xf viewpoint file holds 16 numbers (a 4x4 matrix), found " +
                                 std::to_string(v.size()));
    glm::mat4 m(1);  // glm: m[column][row]
    for (int row = 0; row < int(v.size()) / 4; ++row)
        for (int col = 0; col < 4; ++col) m[col][row] = float(v[size_t(4 * row + col)]);
    if (std::abs(glm::determinant(glm::mat3(m))) < 1e-12f)
        throw std::runtime_error(path + ": the viewpoint matrix is singular");
    return m;
}

void write_xf(const std::string& path, const glm::mat4& view) {
    std::ofstream out(path);
    for (int row = 0; row < 4; ++row) {
        char line[160];
        std::snprintf(line, sizeof line, "%.9g %.9g %.9g %.9g\n", view[0][row], view[1][row], view[2][row],
                      view[3][row]);
        out << line;
    }
    if (!out) throw std::runtime_error(path + ": cannot write the viewpoint file");
}

}  // namespace kappa::render
