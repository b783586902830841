// The per-vertex prefilter of the CPU line pass (render/lines/line_prefilter.h)
// never skips a triangle on which the exact per-triangle tests find a line,
// and skips most triangles.
#include <catch2/catch.hpp>

#include "test_support.h"

#include "geometry/curvature/feature_size.h"
#include "geometry/io/mesh_io.h"
#include "geometry/lines/curvature_lines.h"
#include "geometry/surface_analysis.h"
#include "render/lines/line_prefilter.h"

#include <glm/geometric.hpp>

using namespace kappa;

TEST_CASE("the line prefilter keeps every triangle that holds a line and skips most others", "[render][prefilter]") {
    const Mesh mesh = load_mesh(test::shared_mesh("bunny.ply"));
    const SurfaceFields fields = compute_surface_fields(mesh);
    const float fs = feature_size(mesh, fields);
    LineExtractionOptions o;
    o.contours = o.suggestive = o.suggestive_highlights = o.dwkr = true;
    o.ridges = o.valleys = o.parabolic = o.mean_zero = true;
    o.isophotes = o.topo = true;
    o.feature_size = fs;
    o.light = glm::normalize(glm::vec3(0.3f, 0.5f, 1.0f));
    o.topo_levels = {-0.1f, 0.02f, 12};
    ViewRidgeOptions vr;
    vr.apparent_ridges = vr.principal_highlights = true;
    vr.feature_size = fs;
    for (const glm::vec3 eye : {glm::vec3(0.0f, 0.1f, 0.5f), glm::vec3(-0.4f, 0.3f, -0.2f)}) {
        const ViewQuantities q = compute_view_quantities(mesh, fields, {}, eye, fs);
        const std::vector<ViewRidgeVertex> ridges = view_ridge_vertices(mesh, fields, eye, fs);
        const LevelValues levels = level_values(mesh, fields, o);
        const render::LinePrefilter prefilter = render::make_line_prefilter(mesh, fields, q, ridges, vr, levels, o, eye);
        LineExtractionOptions iso = o, topo = o;
        iso.topo = false, topo.isophotes = false;
        size_t missed = 0, with_lines = 0, kept_of[5] = {}, has_of[5] = {};
        for (const Face& t : mesh.faces) {
            const uint8_t families = prefilter.families_on(t, 0x1f);
            auto found_any = [&](auto extract) {
                ExtractedLines lines;
                extract(lines);
                for (const auto& segments : lines)
                    if (!segments.empty()) return true;
                return false;
            };
            const bool has[5] = {
                found_any([&](ExtractedLines& l) { extract_view_lines_of_face(mesh, t, fields, q, o, l); }),
                found_any([&](ExtractedLines& l) { curvature_lines_of_face(mesh, t, fields, o, l); }),
                found_any([&](ExtractedLines& l) {
                    view_ridges_of_face(mesh, t, fields, ridges, vr, l[int(LineType::ApparentRidge)],
                                        l[int(LineType::PrincipalHighlight)]);
                }),
                found_any([&](ExtractedLines& l) { level_lines_of_face(mesh, t, levels, iso, l); }),
                found_any([&](ExtractedLines& l) { level_lines_of_face(mesh, t, levels, topo, l); })};
            bool any = false;
            for (int f = 0; f < 5; ++f) {
                any = any || has[f];
                missed += has[f] && !(families & (1u << f));
                kept_of[f] += (families >> f) & 1u;
                has_of[f] += has[f];
            }
            with_lines += any;
        }
        INFO(mesh.face_count() << " triangles, " << with_lines << " with lines");
        CHECK(with_lines > 1000);
        CHECK(missed == 0);
        // The zero sets and level lines: a sign change (or a band change) at the vertices is nearly
        // always a crossing; the clipped kinds also keep triangles where the clip removes all. For
        // apparent ridges and principal highlights the prefilter knows the signs of the vectors the
        // triangle's tests compare, not the tests (a maximum, a clip): it skips less (measured on
        // these views: 2.4 and 2.8 triangles kept per triangle with lines).
        for (int f : {0, 1, 3, 4}) {
            INFO("family " << f << ": " << has_of[f] << " triangles with lines, " << kept_of[f] << " kept");
            CHECK(kept_of[f] < 2 * has_of[f] + 100);
        }
        INFO("view ridges: " << has_of[2] << " triangles with lines, " << kept_of[2] << " kept");
        CHECK(kept_of[2] < 3 * has_of[2] + 100);

        // Culling back faces (rtsc): triangles turned away keep the contour family alone, the others all.
        LineExtractionOptions cull = o;
        cull.cull_back_faces = true;
        const render::LinePrefilter culled = render::make_line_prefilter(mesh, fields, q, ridges, vr, levels, cull, eye);
        size_t turned_away = 0, wrong = 0;
        for (const Face& t : mesh.faces) {
            const uint8_t all = prefilter.families_on(t, 0x1f) & 0x1f, some = culled.families_on(t, 0x1f) & 0x1f;
            const bool facing = faces_eye(mesh, fields, t, eye);
            turned_away += !facing;
            wrong += facing ? some != all : some != (all & render::kViewLines);
        }
        CHECK(turned_away > mesh.face_count() / 4);
        CHECK(wrong == 0);
    }
}
