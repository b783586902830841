// Drawing quality and cost of --detail (render/fields/detail_fields.h): how well
// drawings of one shape agree across tessellations and noise, and how long
// the fields of a view take. For each detail value (px; 0 = off):
//   - bunny.ply vs bunny-1M.ply (the same scan after two Loop steps), from
//     bunny's default camera;
//   - the built-in shape on a 1.3M-face icosphere with normal noise of 0.3
//     mean edge lengths, an irregular (jittered) 82k-face one and the
//     default 82k-face one, each against the clean 1.3M-face drawing;
//   - scan-like meshes: the built-in shape on irregular (jittered)
//     tessellations of 20k, 82k and 330k faces with normal noise of 0.1,
//     0.33 and 0.5 mean edges, each against its clean tessellation, drawn at
//     800x800 (the 82k one has edges of about 4 px there);
// prints the fraction of each drawing's ink within 2 px of the other's
// (both ways), and the ink counts. Lines only (contours, suggestive),
// 1024x768 (scan-like: 800x800), no MSAA.
//
//   build/bench_render_detail [--details 0,4,8] [--save DIR] [--scans-only] [--only contours|suggestive]
//                            [--write-meshes DIR]   (also writes the scan-like meshes as PLY, for kappa render)
//                            [--decompose]
// --decompose: for the scan-like meshes, also the curvature tensor's RMS
// error at the detail scale against the clean fields', the noisy drawing with
// the clean fields' curvature tensor swapped in (near 100%: the curvature
// fields are the whole gap, not the drawn positions or C), and the clean mesh
// denoised as the noisy one is (what the denoising moves by itself).
#include "geometry/mesh/default_model.h"
#include "geometry/curvature/feature_size.h"
#include "geometry/io/mesh_io.h"
#include "geometry/io/ply_io.h"
#include "geometry/mesh/primitives.h"
#include "geometry/mesh/vertex_faces.h"
#include "geometry/scale/denoise.h"
#include "geometry/scale/tensor3.h"
#include "geometry/surface_analysis.h"
#include "render/fields/detail_fields.h"
#include "render/gl/egl_context.h"
#include "render/image/ink_agreement.h"
#include "render/image/png_writer.h"
#include "render/renderer.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

using namespace kappa;

namespace {

std::string g_only;  // --only contours|suggestive: one line type

struct Subject {
    std::string name;
    Mesh mesh;
    SurfaceFields raw;
    render::DetailSource source;
    double prepare_s = 0;  // make_detail_source (with the denoising of noisy meshes)
};

Subject make_subject(std::string name, Mesh mesh) {
    Subject s{std::move(name), std::move(mesh), {}, {}};
    s.raw = compute_surface_fields(s.mesh);
    const auto t0 = std::chrono::steady_clock::now();
    s.source = render::make_detail_source(s.mesh, s.raw);
    s.prepare_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return s;
}

render::RenderSettings line_settings(float detail) {
    render::RenderSettings settings;
    settings.shading = render::Shading::None;
    settings.msaa = false;
    settings.detail = detail;
    if (g_only == "contours") settings.lines.suggestive = false;
    if (g_only == "suggestive") settings.lines.contours = false;
    return settings;
}

render::Image draw(render::Renderer& renderer, Subject& s, const render::Camera& camera, float detail,
                   double* seconds, int width, int height) {
    const auto t0 = std::chrono::steady_clock::now();
    if (detail > 0) {
        render::DetailFields d = render::detail_fields(s.mesh, s.source, s.raw, camera, height, detail);
        renderer.set_mesh(d.mesh, d.fields, d.feature_size, d.fine_normals);
    } else {
        renderer.set_mesh(s.mesh, s.raw, feature_size(s.mesh, s.raw));
    }
    *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return render::render_to_image(renderer, camera, line_settings(detail), width, height);
}

// --decompose: where a noisy scan's drawing parts from its clean shape's.
// The curvature tensor (k1, k2, directions, normal) as a tensor of 3D space.
Sym3 curvature_tensor(const SurfaceFields& f, size_t v) {
    return embed(Tensor2{f.k1[v], 0, f.k2[v]}, f.d1[v], f.d2[v]);
}

float squared_norm(const Sym3& t) {
    const float* m = t.m;
    return m[0] * m[0] + m[3] * m[3] + m[5] * m[5] + 2 * (m[1] * m[1] + m[2] * m[2] + m[4] * m[4]);
}

// RMS over vertices of |II_a - II_b| relative to the RMS |II_b|.
double curvature_error(const SurfaceFields& a, const SurfaceFields& b) {
    double error = 0, size = 0;
    for (size_t v = 0; v < b.size(); ++v) {
        Sym3 d = curvature_tensor(a, v);
        const Sym3 t = curvature_tensor(b, v);
        for (int i = 0; i < 6; ++i) d.m[i] -= t.m[i];
        error += squared_norm(d), size += squared_norm(t);
    }
    return size > 0 ? std::sqrt(error / size) : 0.0;
}

// The clean mesh through the noisy one's denoising (its noise floor): what
// the denoising alone moves.
Subject denoised_alike(const Subject& clean, const Subject& noisy) {
    Subject s{clean.name + " denoised", clean.mesh, clean.raw, {}};
    s.source.space = build_scale_space(s.mesh);
    s.source.denoised_at = noisy.source.denoised_at;
    denoise_at_floor(s.mesh, s.raw, build_vertex_faces(s.mesh), s.source.denoised_at, s.source.space,
                     s.source.denoised, s.source.denoised_raw);
    return s;
}

void decompose(render::Renderer& renderer, Subject& noisy, Subject& clean, const render::Camera& camera, float detail,
               int width, int height, const render::Image& clean_image) {
    auto report = [&](const char* what, const render::Image& image) {
        std::printf("      %-44s within 2 px: %5.1f%% / %5.1f%%\n", what, 100 * render::ink_within(image, clean_image, 2),
                    100 * render::ink_within(clean_image, image, 2));
    };
    const render::DetailFields c = render::detail_fields(clean.mesh, clean.source, clean.raw, camera, height, detail);
    render::DetailFields n = render::detail_fields(noisy.mesh, noisy.source, noisy.raw, camera, height, detail);
    std::printf("      curvature error at the detail scale: %.1f%%\n", 100 * curvature_error(n.fields, c.fields));
    // The noisy drawing with the clean fields' curvature tensor (C re-expressed in its frame).
    for (size_t v = 0; v < n.fields.size(); ++v) {
        n.fields.dcurv[v] = project_dcurv(n.fields.d1[v], n.fields.d2[v], n.fields.dcurv[v], c.fields.d1[v], c.fields.d2[v]);
        n.fields.normals[v] = c.fields.normals[v];
        n.fields.k1[v] = c.fields.k1[v], n.fields.k2[v] = c.fields.k2[v];
        n.fields.d1[v] = c.fields.d1[v], n.fields.d2[v] = c.fields.d2[v];
    }
    renderer.set_mesh(n.mesh, n.fields, n.feature_size, n.fine_normals);
    report("noisy, with the clean curvature tensor", render::render_to_image(renderer, camera, line_settings(detail), width, height));
    if (noisy.source.denoised_at > 0) {
        Subject alike = denoised_alike(clean, noisy);
        double seconds = 0;
        report("clean, denoised as the noisy one", draw(renderer, alike, camera, detail, &seconds, width, height));
    }
}

float mean_edge(const Mesh& mesh) {
    float edge = 0;
    for (const Face& f : mesh.faces)
        for (int k = 0; k < 3; ++k) edge += glm::length(mesh.positions[f[k]] - mesh.positions[f[(k + 1) % 3]]);
    return edge / float(3 * mesh.face_count());
}

struct Pair {
    Subject a, b;
    int width = 1024, height = 768;
};

}  // namespace

int main(int argc, char** argv) {
    std::vector<float> details = {0, 4, 6, 8, 12};
    std::string save;
    bool scans_only = false, decomposed = false;
    std::string write_meshes;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--details") && i + 1 < argc) {
            details.clear();
            std::stringstream list(argv[++i]);
            for (std::string item; std::getline(list, item, ',');) details.push_back(std::stof(item));
        } else if (!std::strcmp(argv[i], "--save") && i + 1 < argc) {
            save = argv[++i];
        } else if (!std::strcmp(argv[i], "--write-meshes") && i + 1 < argc) {
            write_meshes = argv[++i];
        } else if (!std::strcmp(argv[i], "--only") && i + 1 < argc) {
            g_only = argv[++i];
        } else if (!std::strcmp(argv[i], "--scans-only")) {
            scans_only = true;
        } else if (!std::strcmp(argv[i], "--decompose")) {
            decomposed = true;
        }
    }
    const std::string dir = std::string(KAPPA_SOURCE_DIR) + "/../shared/meshes/";
    auto context = render::HeadlessContext::create();
    render::Renderer renderer;

    std::vector<Pair> pairs;
    if (!scans_only) {
        pairs.push_back({make_subject("bunny", load_mesh(dir + "bunny.ply")),
                         make_subject("bunny-1M", load_mesh(dir + "bunny-1M.ply"))});
        Mesh fine = make_default_model_from(make_icosphere(1.0f, 8));
        Mesh noisy = fine;
        add_normal_noise(noisy, 0.3f * mean_edge(fine), 7);
        Subject clean = make_subject("blob-1.3M", std::move(fine));
        pairs.push_back({make_subject("blob-1.3M+noise", std::move(noisy)), clean});
        pairs.push_back({make_subject("blob-irregular", make_default_model_from(make_jittered_sphere(1.0f, 6, 0.8f, 3))),
                         clean});
        pairs.push_back({make_subject("blob-82k", make_default_model()), clean});
    }
    for (int level : {5, 6, 7}) {  // scan-like: irregular tessellations with normal noise
        const Mesh clean_mesh = make_default_model_from(make_jittered_sphere(1.0f, level, 0.8f, 3));
        const Subject clean = make_subject("irr" + std::to_string(level), clean_mesh);
        for (float noise : {0.1f, 0.33f, 0.5f}) {
            Mesh noisy = clean_mesh;
            add_normal_noise(noisy, noise * mean_edge(clean_mesh), 11);
            char name[32];
            std::snprintf(name, sizeof name, "irr%d+%.2g", level, noise);
            pairs.push_back({make_subject(name, std::move(noisy)), clean, 800, 800});

        }
    }

    for (const Pair& p : pairs)
        for (const Subject* s : {&p.a, &p.b}) {
            if (!write_meshes.empty() && p.width == 800) write_ply(write_meshes + "/" + s->name + ".ply", s->mesh, s->raw);
            const float h = mean_edge(s->mesh);
            std::printf("%-16s denoised at %.2f edges, then noise floor %.2f, contour floor %.2f edges; %.3f s\n",
                        s->name.c_str(), s->source.denoised_at / h, s->source.noise_floor / h,
                        s->source.contour_floor / h, s->prepare_s);
        }
    for (float detail : details) {
        std::printf("detail %g px\n", detail);
        for (auto& [a, b, width, height] : pairs) {
            const render::Camera camera =
                render::Camera::framing(render::bounding_sphere(b.mesh), 30.0f, float(width) / float(height));
            double ta = 0, tb = 0;
            const render::Image ia = draw(renderer, a, camera, detail, &ta, width, height);
            const render::Image ib = draw(renderer, b, camera, detail, &tb, width, height);
            std::printf("  %-16s vs %-10s  ink %7zu / %7zu   within 2 px: %5.1f%% / %5.1f%%   fields %.3f / %.3f s\n",
                        a.name.c_str(), b.name.c_str(), render::count_ink(ia), render::count_ink(ib),
                        100 * render::ink_within(ia, ib, 2), 100 * render::ink_within(ib, ia, 2), ta, tb);
            if (decomposed && width == 800) decompose(renderer, a, b, camera, detail, width, height, ib);
            if (!save.empty()) {
                char suffix[32];
                std::snprintf(suffix, sizeof suffix, "-d%g.png", detail);
                render::write_png(save + "/" + a.name + suffix, ia);
                render::write_png(save + "/" + b.name + suffix, ib);
            }
        }
        std::fflush(stdout);
    }
    return 0;
}
