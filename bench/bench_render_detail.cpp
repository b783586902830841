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
#include "geometry/mesh/default_model.h"
#include "geometry/curvature/feature_size.h"
#include "geometry/io/mesh_io.h"
#include "geometry/io/ply_io.h"
#include "geometry/mesh/primitives.h"
#include "geometry/surface_analysis.h"
#include "render/fields/detail_fields.h"
#include "render/gl/egl_context.h"
#include "render/image/ink_agreement.h"
#include "render/image/png_writer.h"
#include "render/renderer.h"

#include <chrono>
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

render::Image draw(render::Renderer& renderer, Subject& s, const render::Camera& camera, float detail,
                   double* seconds, int width, int height) {
    render::RenderSettings settings;
    settings.shading = render::Shading::None;
    settings.msaa = false;
    settings.detail = detail;
    if (g_only == "contours") settings.lines.suggestive = false;
    if (g_only == "suggestive") settings.lines.contours = false;
    const auto t0 = std::chrono::steady_clock::now();
    if (detail > 0) {
        render::DetailFields d = render::detail_fields(s.mesh, s.source, s.raw, camera, height, detail);
        renderer.set_mesh(d.mesh, d.fields, d.feature_size, d.fine_normals);
    } else {
        renderer.set_mesh(s.mesh, s.raw, feature_size(s.mesh, s.raw));
    }
    *seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return render::render_to_image(renderer, camera, settings, width, height);
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
    bool scans_only = false;
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
