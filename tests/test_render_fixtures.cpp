#include <algorithm>
#include "test_render_fixtures.h"

#include "test_support.h"

#include "geometry/curvature/feature_size.h"
#include "geometry/io/mesh_io.h"
#include "geometry/surface_analysis.h"
#include "render/gl/egl_context.h"
#include "render/image/ink_agreement.h"
#include "render/image/png_writer.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdlib>
#include <memory>

namespace kappa::test {

render::Renderer& renderer() {
    static std::unique_ptr<render::HeadlessContext> context = render::HeadlessContext::create();
    static render::Renderer r;
    return r;
}

render::BoundingSphere upload_shared_bunny() {
    const Mesh bunny = load_mesh(shared_mesh("bunny.ply"));
    const SurfaceFields fields = compute_surface_fields(bunny);
    renderer().set_mesh(bunny, fields, feature_size(bunny, fields));
    return render::bounding_sphere(bunny);
}

namespace {

// A unit tangent at normal n, any direction.
glm::vec3 any_tangent(glm::vec3 n) {
    const glm::vec3 a = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    return glm::normalize(glm::cross(n, a));
}

SurfaceFields empty_fields(size_t n) {
    SurfaceFields f;
    f.normals.resize(n);
    f.point_areas.assign(n, 1.0f);
    f.k1.assign(n, 0);
    f.k2.assign(n, 0);
    f.d1.resize(n);
    f.d2.resize(n);
    f.dcurv.assign(n, glm::vec4(0));
    f.flags.assign(n, 0);
    return f;
}

}  // namespace

SurfaceFields sphere_fields(const Mesh& mesh, float radius) {
    SurfaceFields f = empty_fields(mesh.vertex_count());
    for (size_t i = 0; i < mesh.vertex_count(); ++i) {
        const glm::vec3 n = glm::normalize(mesh.positions[i]);
        f.normals[i] = n;
        f.k1[i] = f.k2[i] = 1.0f / radius;
        f.d1[i] = any_tangent(n);
        f.d2[i] = glm::cross(n, f.d1[i]);  // d1 x d2 = n
    }
    return f;
}

SurfaceFields torus_fields(const Mesh& mesh, float R, float r) {
    SurfaceFields f = empty_fields(mesh.vertex_count());
    for (size_t i = 0; i < mesh.vertex_count(); ++i) {
        const glm::vec3 p = mesh.positions[i];
        const float u = std::atan2(p.y, p.x);
        const float v = std::atan2(p.z, std::sqrt(p.x * p.x + p.y * p.y) - R);
        const float cu = std::cos(u), su = std::sin(u), cv = std::cos(v), sv = std::sin(v);
        f.normals[i] = {cv * cu, cv * su, sv};
        f.k1[i] = 1.0f / r;                  // along the tube
        f.k2[i] = cv / (R + r * cv);         // along the big circle
        f.d1[i] = {-sv * cu, -sv * su, cv};  // d/dv
        f.d2[i] = {su, -cu, 0};              // so that d1 x d2 = n
        // C122 = d k2 / ds along d1 (arc length s = r v); every other entry is 0.
        const float c = -R * sv / (r * (R + r * cv) * (R + r * cv));
        f.dcurv[i] = {0, 0, c, 0};
    }
    return f;
}

SurfaceFields flat_fields(const Mesh& mesh) {
    SurfaceFields f = empty_fields(mesh.vertex_count());
    for (size_t i = 0; i < mesh.vertex_count(); ++i) {
        f.normals[i] = {0, 0, 1};
        f.d1[i] = {1, 0, 0};
        f.d2[i] = {0, 1, 0};
    }
    return f;
}

render::RenderSettings lines_only(render::LineSelection lines) {
    render::RenderSettings s;
    s.lines = lines;
    s.shading = render::Shading::None;
    s.colormap = render::ColorMap::None;
    s.msaa = false;
    s.line_width = 2.0f;
    return s;
}

render::Image render(const Mesh& mesh, const SurfaceFields& fields, float fs, const render::Camera& camera,
                     const render::RenderSettings& settings, int width, int height) {
    render::Renderer& r = renderer();
    r.set_mesh(mesh, fields, fs);
    return render::render_to_image(r, camera, settings, width, height);
}

bool is_ink(const render::Rgba& c) { return render::is_ink(c); }

size_t count_ink(const render::Image& image) { return render::count_ink(image); }

size_t differing_pixels(const render::Image& a, const render::Image& b) {
    size_t n = 0;
    auto far = [&](size_t i) { return std::abs(int(a.pixels[i]) - int(b.pixels[i])) > 64; };
    for (size_t i = 0; i < a.pixels.size(); i += 4) n += far(i) || far(i + 1) || far(i + 2);
    return n;
}

int largest_difference(const render::Image& a, const render::Image& b) {
    int largest = a.pixels.size() == b.pixels.size() ? 0 : 255;
    for (size_t i = 0; i < std::min(a.pixels.size(), b.pixels.size()); ++i)
        largest = std::max(largest, std::abs(int(a.pixels[i]) - int(b.pixels[i])));
    return largest;
}

glm::vec2 project(const render::Camera& camera, const render::BoundingSphere& bounds, glm::vec3 point, int width,
                  int height) {
    const glm::mat4 mvp = camera.projection(bounds, float(width) / float(height)) * camera.view;
    const glm::vec4 c = mvp * glm::vec4(point, 1);
    const glm::vec2 ndc = glm::vec2(c) / c.w;
    return {(ndc.x * 0.5f + 0.5f) * float(width), (0.5f - ndc.y * 0.5f) * float(height)};
}

void maybe_save(const render::Image& image, const std::string& name) {
    if (const char* dir = std::getenv("KAPPA_TEST_PNG_DIR")) render::write_png(std::string(dir) + "/" + name + ".png", image);
}

}  // namespace kappa::test
