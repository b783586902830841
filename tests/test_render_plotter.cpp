// Vector clean-up and --plotter (render/vector/stroke_cleanup.h, render/vector/plotter.h):
// on synthetic strokes where the answer is known, and on real drawings
// written by `kappa render --plotter` and read back from the SVG.
#include <catch2/catch.hpp>

#include "test_support.h"

#include "render/image/ink_agreement.h"
#include "render/image/png_writer.h"
#include "render/vector/plotter.h"
#include "render/vector/stroke_cleanup.h"
#include "render/vector/vector_drawing.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdlib>
#include <sstream>

using namespace kappa;
using render::Stroke;

namespace {

Stroke stroke(std::vector<glm::vec2> points, LineType type = LineType::Contour) {
    Stroke s;
    s.type = type;
    s.opacity.assign(points.size(), 1.0f);
    s.points = std::move(points);
    return s;
}

// The paths of an SVG written by kappa ("M x y L x y x y ..."), in file order.
std::vector<Stroke> svg_paths(const std::string& svg) {
    std::vector<Stroke> out;
    for (size_t at = svg.find("<path d=\"M"); at != std::string::npos; at = svg.find("<path d=\"M", at + 1)) {
        const size_t end = svg.find('"', at + 9);
        std::string d = svg.substr(at + 10, end - at - 10);
        for (char& c : d)
            if (c == 'L') c = ' ';
        std::istringstream in(d);
        std::vector<glm::vec2> points;
        float x, y;
        while (in >> x >> y) points.push_back({x, y});
        out.push_back(stroke(points));
    }
    return out;
}

// Length of path a lying within `radius` of path b (sampled every 0.1 px).
float overlap_length(const Stroke& a, const Stroke& b, float radius) {
    auto near_b = [&](glm::vec2 p) {
        for (size_t i = 0; i + 1 < b.points.size(); ++i) {
            const glm::vec2 u = b.points[i], v = b.points[i + 1], uv = v - u;
            const float len2 = glm::dot(uv, uv);
            const float t = len2 > 0 ? glm::clamp(glm::dot(p - u, uv) / len2, 0.0f, 1.0f) : 0.0f;
            if (glm::distance(p, u + t * uv) <= radius) return true;
        }
        return false;
    };
    float length = 0;
    for (size_t i = 0; i + 1 < a.points.size(); ++i) {
        const float len = glm::distance(a.points[i], a.points[i + 1]);
        const int steps = std::max(1, int(std::ceil(len / 0.1f)));
        for (int k = 0; k < steps; ++k)
            if (near_b(a.points[i] + (a.points[i + 1] - a.points[i]) * ((float(k) + 0.5f) / float(steps))))
                length += len / float(steps);
    }
    return length;
}

// Bounding boxes first: most pairs of paths are far apart.
float worst_overlap(const std::vector<Stroke>& paths) {
    std::vector<glm::vec4> box;
    for (const Stroke& s : paths) {
        glm::vec4 b(1e9f, 1e9f, -1e9f, -1e9f);
        for (glm::vec2 p : s.points) b = {std::min(b.x, p.x), std::min(b.y, p.y), std::max(b.z, p.x), std::max(b.w, p.y)};
        box.push_back(b);
    }
    float worst = 0;
    for (size_t i = 0; i < paths.size(); ++i)
        for (size_t j = 0; j < paths.size(); ++j)
            if (i != j && box[i].x <= box[j].z + 1 && box[j].x <= box[i].z + 1 && box[i].y <= box[j].w + 1 &&
                box[j].y <= box[i].w + 1)
                worst = std::max(worst, overlap_length(paths[i], paths[j], 0.5f));
    return worst;
}

}  // namespace

TEST_CASE("simplify_strokes keeps every removed point within the tolerance, and drop_short_strokes drops short ones", "[render][vector]") {
    std::vector<glm::vec2> wiggle;
    for (int i = 0; i <= 200; ++i) wiggle.push_back({float(i) * 0.5f, 0.1f * std::sin(float(i))});
    std::vector<Stroke> strokes{stroke(wiggle), stroke({{0, 50}, {1, 50}})};
    const Stroke original = strokes[0];
    render::simplify_strokes(strokes, 0.25f);
    CHECK(strokes[0].points.size() == 2);  // a 0.1 px wiggle is a straight line at 0.25 px
    render::simplify_strokes(strokes = {original}, 0.05f);
    CHECK(strokes[0].points.size() > 50);
    for (glm::vec2 p : original.points) {  // no point of the original is farther than 0.05 from the result
        float d = 1e9f;
        const auto& q = strokes[0].points;
        for (size_t i = 0; i + 1 < q.size(); ++i) {
            const glm::vec2 uv = q[i + 1] - q[i];
            const float t = glm::clamp(glm::dot(p - q[i], uv) / glm::dot(uv, uv), 0.0f, 1.0f);
            d = std::min(d, glm::distance(p, q[i] + t * uv));
        }
        CHECK(d <= 0.05f + 1e-4f);
    }
    std::vector<Stroke> short_and_long{stroke({{0, 0}, {1.5f, 0}}), stroke({{0, 10}, {30, 10}})};
    render::drop_short_strokes(short_and_long, 2.0f);
    REQUIRE(short_and_long.size() == 1);
    CHECK(render::stroke_length(short_and_long[0]) == Approx(30.0f));
}

TEST_CASE("plotter_paths: duplicates removed, touching paths joined, faded parts cut, travel shortened", "[render][vector]") {
    // The same line twice, a path continuing it, and a far one given first.
    std::vector<Stroke> in{stroke({{500, 500}, {520, 500}}), stroke({{0, 10}, {100, 10}}), stroke({{0, 10.3f}, {100, 10.3f}}),
                           stroke({{100.2f, 10}, {100.2f, 60}})};
    Stroke faded = stroke({{0, 200}, {100, 200}});
    faded.opacity = {0.0f, 1.0f};  // half ink from x = 50 on
    in.push_back(faded);
    const double unordered = render::pen_up_travel(in);
    const std::vector<Stroke> out = render::plotter_paths(in);
    CHECK(worst_overlap(out) <= 1.0f);
    float total = 0;
    for (const Stroke& s : out) total += render::stroke_length(s);
    // 100 (the line once) + 50 (its continuation, joined) + 20 + 50 (the faded line's inked half).
    CHECK(total == Approx(220.0f).margin(2.0f));
    INFO(out.size() << " paths");
    CHECK(out.size() == 3);
    CHECK(render::pen_up_travel(out) <= unordered);
    for (const Stroke& s : out)
        for (float o : s.opacity) CHECK(o == 1.0f);
}

TEST_CASE("kappa render --plotter: no path drawn twice, less pen travel than the plain SVG", "[render][cli][vector]") {
    for (const std::string& mesh : {test::shared_mesh("bunny.ply"), test::shared_mesh("fandisk.obj")}) {
        const std::string dir = test::temp_dir();
        const std::string base = std::string(KAPPA_EXE) + " render " + mesh + " --shading none -q --size 800x600";
        REQUIRE(test::run_command(base + " -o " + dir + "/plain.svg").exit_code == 0);
        REQUIRE(test::run_command(base + " --plotter -o " + dir + "/plotter.svg").exit_code == 0);
        const std::string plotter_svg = test::read_file(dir + "/plotter.svg");
        const std::vector<Stroke> plain = svg_paths(test::read_file(dir + "/plain.svg"));
        const std::vector<Stroke> plotter = svg_paths(plotter_svg);
        INFO(mesh << ": " << plain.size() << " plain paths, " << plotter.size() << " plotter paths");
        REQUIRE(!plotter.empty());
        CHECK(plotter.size() < plain.size());  // joined
        CHECK(worst_overlap(plotter) <= 1.0f);
        CHECK(render::pen_up_travel(plotter) <= render::pen_up_travel(plain));
        CHECK(plotter_svg.find("stroke-opacity") == std::string::npos);  // one pen: full ink, one width
        auto count = [&](const std::string& what) {
            size_t n = 0;
            for (size_t at = plotter_svg.find(what); at != std::string::npos; at = plotter_svg.find(what, at + 1)) ++n;
            return n;
        };
        CHECK(count("stroke-width") == count("inkscape:groupmode"));  // set once per layer, never per path
        // And the drawing is still there: the plotter SVG rasterised by
        // another program (rsvg-convert) agrees with the PNG of the same view
        // both ways, as the plain SVG does (test_render_vector_output.cpp).
        REQUIRE(test::run_command(base + " -o " + dir + "/plain.png").exit_code == 0);
        REQUIRE(test::run_command("rsvg-convert " + dir + "/plotter.svg -o " + dir + "/plotter.png").exit_code == 0);
        const render::Image png = render::read_png(dir + "/plain.png"), drawn = render::read_png(dir + "/plotter.png");
        REQUIRE(drawn.width == png.width);
        REQUIRE(drawn.height == png.height);
        const double plotter_near_png = render::ink_within(drawn, png, 2.0f);
        const double png_near_plotter = render::ink_within(png, drawn, 2.0f);
        INFO("ink " << render::count_ink(png) << " in the PNG, " << render::count_ink(drawn) << " in the plotter SVG; "
                    << "plotter ink near the PNG's " << plotter_near_png << ", and back " << png_near_plotter);
        CHECK(render::count_ink(png) > 1000);
        CHECK(plotter_near_png >= 0.95);
        CHECK(png_near_plotter >= 0.95);
    }
}

TEST_CASE("stroke_pieces: tapered ends and width by strength", "[render][vector]") {
    render::VectorDrawing d;
    d.line_width = 2;
    d.taper = 10;
    const std::vector<render::StrokePiece> tapered = render::stroke_pieces(stroke({{0, 0}, {100, 0}}), d);
    REQUIRE(tapered.size() >= 3);
    CHECK(tapered.front().width < 0.5f * d.line_width);  // thin at the ends, about 0.2 of the width
    CHECK(tapered.back().width < 0.5f * d.line_width);
    CHECK(tapered.front().width >= 0.2f * d.line_width - 1e-6f);
    float widest = 0;
    for (const auto& p : tapered) widest = std::max(widest, p.width);
    CHECK(widest == d.line_width);  // full width away from the ends
    d.taper = 0;
    d.width_by_strength = true;
    Stroke weak = stroke({{0, 0}, {10, 0}});
    weak.opacity = {0.5f, 0.5f};
    const std::vector<render::StrokePiece> thin = render::stroke_pieces(weak, d);
    REQUIRE(thin.size() == 1);
    CHECK(thin[0].width == Approx(0.5f * d.line_width));
    CHECK(thin[0].opacity == 1.0f);
}
