// `kappa render -o out.svg|out.pdf`: vector output read back by other
// programs (rsvg-convert from librsvg2-bin, pdftoppm from poppler-utils) and
// compared with kappa's own PNG of the same view, as a person would: nearly
// all ink of each within 2 px of the other's.
#include <catch2/catch.hpp>

#include "test_render_fixtures.h"
#include "test_support.h"

#include "render/image/ink_agreement.h"
#include "render/image/png_writer.h"

#include <string>

using namespace kappa;
using test::kappa_render;

namespace {

// Renders `mesh` (empty: the built-in model) as PNG and as `ext`, rasterises
// the vector file with another program and returns both images.
std::pair<render::Image, render::Image> png_and_vector(const std::string& mesh, const std::string& ext,
                                                       const std::string& options = "--shading none") {
    const std::string dir = test::temp_dir();
    const std::string common = mesh + " --size 800x600 -q " + options;
    auto run = [](const std::string& command) {
        const auto r = test::run_command(command);
        INFO(command << "\n" << r.output);
        REQUIRE(r.exit_code == 0);
    };
    run(kappa_render(common + " -o " + dir + "/raster.png"));
    run(kappa_render(common + " -o " + dir + "/vector." + ext));
    if (ext == "svg") run("rsvg-convert " + dir + "/vector.svg -o " + dir + "/vector.png");
    else run("pdftoppm -png -r 72 -singlefile " + dir + "/vector.pdf " + dir + "/vector");
    return {render::read_png(dir + "/raster.png"), render::read_png(dir + "/vector.png")};
}

void check_agreement(const render::Image& raster, const render::Image& vector) {
    REQUIRE(vector.width == raster.width);
    REQUIRE(vector.height == raster.height);
    const double vector_near_raster = render::ink_within(vector, raster, 2.0f);
    const double raster_near_vector = render::ink_within(raster, vector, 2.0f);
    WARN("ink of the vector file near the PNG's: " << vector_near_raster << ", and back: " << raster_near_vector);
    CHECK(render::count_ink(raster) > 1000);
    CHECK(vector_near_raster >= 0.95);
    CHECK(raster_near_vector >= 0.95);
}

}  // namespace

TEST_CASE("SVG output agrees with the PNG of the same view (rsvg-convert)", "[render][cli][vector]") {
    for (const std::string& mesh : {std::string(), test::shared_mesh("bunny.ply"), test::shared_mesh("fandisk.obj")}) {
        INFO("mesh: " << (mesh.empty() ? "built-in" : mesh));
        const auto [raster, vector] = png_and_vector(mesh, "svg");
        check_agreement(raster, vector);
    }
}

TEST_CASE("PDF output agrees with the PNG of the same view (pdftoppm)", "[render][cli][vector]") {
    for (const std::string& mesh : {std::string(), test::shared_mesh("bunny.ply"), test::shared_mesh("fandisk.obj")}) {
        INFO("mesh: " << (mesh.empty() ? "built-in" : mesh));
        const auto [raster, vector] = png_and_vector(mesh, "pdf");
        check_agreement(raster, vector);
    }
}

TEST_CASE("SVG output is well-formed XML with one Inkscape layer per line type", "[render][cli][vector]") {
    const std::string dir = test::temp_dir(), out = dir + "/fandisk.svg";
    const auto r = test::run_command(kappa_render(test::shared_mesh("fandisk.obj") + " -q --shading none -o " + out));
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    const auto xml = test::run_command("python3 -c 'import sys, xml.dom.minidom; xml.dom.minidom.parse(sys.argv[1])' " + out);
    INFO(xml.output);
    CHECK(xml.exit_code == 0);
    const std::string svg = test::read_file(out);
    for (const char* layer : {"contours", "suggestive", "creases"})
        CHECK(svg.find(std::string("inkscape:groupmode=\"layer\" id=\"") + layer + "\"") != std::string::npos);
    CHECK(svg.find("<image") == std::string::npos);  // --shading none: pure vectors
}

TEST_CASE("SVG with shading embeds the surface as a raster under the strokes", "[render][cli][vector]") {
    const auto [raster, vector] = png_and_vector("", "svg", "--shading lambert");
    // The shaded surface comes through: most pixels of the model are grey,
    // not white, in both.
    size_t grey_raster = 0, grey_vector = 0;
    for (int y = 0; y < raster.height; ++y)
        for (int x = 0; x < raster.width; ++x) {
            grey_raster += raster.at(x, y).r < 250 && raster.at(x, y).r > 60;
            grey_vector += vector.at(x, y).r < 250 && vector.at(x, y).r > 60;
        }
    CHECK(grey_raster > 50000);
    CHECK(double(grey_vector) > 0.95 * double(grey_raster));
    CHECK(double(grey_vector) < 1.05 * double(grey_raster));
}

TEST_CASE("kappa render refuses unknown output formats before reading the mesh", "[render][cli][vector]") {
    const auto r = test::run_command(kappa_render("no-such-mesh.ply -o out.eps"));
    CHECK(r.exit_code == 2);
    CHECK(r.output.find(".svg or .pdf") != std::string::npos);
}

TEST_CASE("Hatching comes out as strokes in SVG and PDF, matching the PNG", "[render][cli][vector][hatching]") {
    for (const char* ext : {"svg", "pdf"}) {
        INFO(ext);
        const auto [raster, vector] = png_and_vector(test::shared_mesh("spot.obj"), ext, "--shading none --hatching cross");
        check_agreement(raster, vector);
    }
}

TEST_CASE("Inkscape opens kappa's SVG headless and draws what the PNG shows", "[render][cli][vector]") {
    const std::string dir = test::temp_dir();
    const std::string common = test::shared_mesh("fandisk.obj") + " --size 800x600 -q --shading none";
    REQUIRE(test::run_command(kappa_render(common + " -o " + dir + "/raster.png")).exit_code == 0);
    REQUIRE(test::run_command(kappa_render(common + " -o " + dir + "/vector.svg")).exit_code == 0);
    // Inkscape wants a writable home for its preferences.
    const auto r = test::run_command("HOME=" + dir + " inkscape --export-type=png --export-background=white "
                                     "--export-background-opacity=1 --export-filename=" + dir + "/inkscape.png " +
                                     dir + "/vector.svg");
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    check_agreement(render::read_png(dir + "/raster.png"), render::read_png(dir + "/inkscape.png"));
}

TEST_CASE("Every line type comes out in SVG as in the PNG", "[render][cli][vector]") {
    // Without fading: a faded line's ink depends on how translucent pieces
    // overlap, which SVG and the GL_MAX blending of the raster do differently.
    const std::string mesh = test::shared_mesh("spot.obj");
    for (const char* lines : {"ridges,valleys,parabolic,mean-zero", "isophotes,topo", "suggestive-highlights,dwkr,boundaries",
                              "apparent-ridges,principal-highlights"}) {
        INFO(lines);
        const auto [raster, vector] = png_and_vector(mesh, "svg", std::string("--shading none --fade off --lines ") + lines);
        check_agreement(raster, vector);
    }
}

TEST_CASE("SVG: silhouette alone and hidden lines as the PNG draws them", "[render][cli][vector]") {
    {
        INFO("--lines silhouette: the exterior outline only");
        const auto [raster, vector] = png_and_vector(test::shared_mesh("bunny.ply"), "svg", "--shading none --lines silhouette");
        check_agreement(raster, vector);
    }
    // Hidden parts: a layer of their own, dashed and light; the visible drawing is the same.
    const std::string dir = test::temp_dir();
    const std::string common = kappa_render(test::shared_mesh("fandisk.obj") + " -q --shading none --size 800x600");
    REQUIRE(test::run_command(common + " -o " + dir + "/plain.svg").exit_code == 0);
    REQUIRE(test::run_command(common + " --hidden-lines on -o " + dir + "/hidden.svg").exit_code == 0);
    const std::string plain = test::read_file(dir + "/plain.svg"), hidden = test::read_file(dir + "/hidden.svg");
    CHECK(plain.find("id=\"hidden\"") == std::string::npos);
    const size_t layer = hidden.find("id=\"hidden\"");
    REQUIRE(layer != std::string::npos);
    const size_t layer_end = hidden.find("</g>", layer);
    CHECK(hidden.find("stroke-dasharray=\"6 4\"", layer) < layer_end);
    CHECK(hidden.find("<path", layer) < layer_end);  // fandisk has hidden edges
    // The dashes are light (35% ink: not ink); the rest draws as without hidden lines.
    REQUIRE(test::run_command("rsvg-convert " + dir + "/plain.svg -o " + dir + "/plain.png").exit_code == 0);
    REQUIRE(test::run_command("rsvg-convert " + dir + "/hidden.svg -o " + dir + "/hidden.png").exit_code == 0);
    check_agreement(render::read_png(dir + "/plain.png"), render::read_png(dir + "/hidden.png"));
}

TEST_CASE("A turntable writes numbered SVG files, each a different view", "[render][cli][vector]") {
    const std::string dir = test::temp_dir();
    const auto r = test::run_command(kappa_render("-q --shading none --size 200x150 --turntable 3 -o " + dir + "/turn.svg"));
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    const std::string a = test::read_file(dir + "/turn-000.svg"), b = test::read_file(dir + "/turn-001.svg");
    CHECK(test::read_file(dir + "/turn-002.svg").find("<path") != std::string::npos);
    CHECK(a.find("<path") != std::string::npos);
    CHECK(a != b);
}
