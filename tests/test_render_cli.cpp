// `kappa render` end to end: the real executable, real files.
#include <catch2/catch.hpp>

#include "test_render_fixtures.h"
#include "test_shapes.h"
#include "test_support.h"

#include "geometry/view/default_view.h"
#include "render/camera/camera.h"
#include "render/image/ink_agreement.h"
#include "render/image/png_writer.h"
#include "geometry/io/mesh_io.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>

using namespace kappa;
using test::kappa_render;


TEST_CASE("kappa render writes a PNG of the requested size and says what it did", "[render][cli]") {
    const std::string dir = test::temp_dir(), out = dir + "/blob.png";
    const auto r = test::run_command(kappa_render("-o " + out + " --size 160x120 --shading none --lines contours"));
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    CHECK(r.output.find("wrote " + out) != std::string::npos);
    CHECK(r.output.find("render") != std::string::npos);  // timings
    const render::Image image = render::read_png(out);
    CHECK(image.width == 160);
    CHECK(image.height == 120);
    CHECK(test::count_ink(image) > 100);          // the contour of the built-in model
    CHECK(image.at(0, 0).r == 255);               // white paper around it
    CHECK(image.at(0, 0).a == 255);
}

TEST_CASE("kappa render: transparent background", "[render][cli]") {
    const std::string dir = test::temp_dir(), out = dir + "/t.png";
    const auto r = test::run_command(kappa_render("-o " + out + " --size 96x96 --background transparent -q"));
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    const render::Image image = render::read_png(out);
    CHECK(image.at(0, 0).a == 0);
    CHECK(image.at(48, 48).a == 255);
}

TEST_CASE("kappa render: --line-color draws the lines in that colour", "[render][cli]") {
    const std::string dir = test::temp_dir(), out = dir + "/red.png";
    const auto r = test::run_command(
        kappa_render("-o " + out + " --size 160x120 --shading none --lines contours --line-color '#ff0000' -q"));
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    const render::Image image = render::read_png(out);
    size_t red = 0, dark = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const render::Rgba c = image.at(x, y);
            red += c.r == 255 && c.g < 128 && c.b == c.g;  // red ink over white: (1, 1 - a, 1 - a)
            dark += c.r < 128;
        }
    CHECK(red > 100);
    CHECK(dark == 0);
    const auto bad = test::run_command(kappa_render("-o " + dir + "/x.png --line-color transparent"));
    CHECK(bad.exit_code != 0);
    CHECK(bad.output.find("--line-color") != std::string::npos);
}

TEST_CASE("kappa render: --turntable writes numbered views that differ", "[render][cli]") {
    const std::string dir = test::temp_dir();
    const auto r = test::run_command(kappa_render("-o " + dir + "/turn.png --size 64x64 --turntable 3 -q"));
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    const auto a = render::read_png(dir + "/turn-000.png"), b = render::read_png(dir + "/turn-001.png"),
               c = render::read_png(dir + "/turn-002.png");
    CHECK(a.pixels != b.pixels);
    CHECK(b.pixels != c.pixels);
    CHECK_FALSE(std::filesystem::exists(dir + "/turn.png"));
}

TEST_CASE("kappa render: a .xf viewpoint gives the same image as the equivalent --eye camera", "[render][cli]") {
    const std::string dir = test::temp_dir();
    const glm::mat4 view = glm::lookAt(glm::vec3(0.5f, -2.6f, 1.85f), glm::vec3(0), glm::vec3(0, 0, 1));
    render::write_xf(dir + "/view.xf", view);
    const glm::mat4 back = render::read_xf(dir + "/view.xf");
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) REQUIRE(back[c][r] == Approx(view[c][r]).margin(1e-6));
    const std::string common = " --size 128x96 --fov 27.5 -q";
    const auto a = test::run_command(kappa_render("-o " + dir + "/a.png --xf " + dir + "/view.xf" + common));
    const auto b = test::run_command(
        kappa_render("-o " + dir + "/b.png --eye 0.5,-2.6,1.85 --target 0,0,0 --up 0,0,1" + common));
    INFO(a.output << b.output);
    REQUIRE(a.exit_code == 0);
    REQUIRE(b.exit_code == 0);
    const auto ia = render::read_png(dir + "/a.png"), ib = render::read_png(dir + "/b.png");
    size_t differ = 0;
    for (size_t i = 0; i < ia.pixels.size(); ++i) differ += std::abs(int(ia.pixels[i]) - int(ib.pixels[i])) > 8;
    CHECK(differ < ia.pixels.size() / 1000);
}

TEST_CASE("kappa render: errors are one clear line", "[render][cli]") {
    const std::string dir = test::temp_dir();
    SECTION("missing mesh file: exit 1, names the file") {
        const auto r = test::run_command(kappa_render(dir + "/nope.ply -o " + dir + "/x.png"));
        CHECK(r.exit_code == 1);
        CHECK(r.output.find("nope.ply") != std::string::npos);
        CHECK(std::count(r.output.begin(), r.output.end(), '\n') == 1);
    }
    SECTION("bad option values: exit 2") {
        for (const char* args : {"--lines contours,wiggles", "--shading glossy", "--colormap rainbow", "--size 12",
                                 "--background '#12345'", "--fade maybe", "--hatching diagonal"}) {
            const auto r = test::run_command(kappa_render("-o " + dir + "/x.png " + args));
            INFO(args << ": " << r.output);
            CHECK(r.exit_code == 2);
            CHECK(std::count(r.output.begin(), r.output.end(), '\n') == 1);
        }
    }
    SECTION("missing output") {
        CHECK(test::run_command(kappa_render("")).exit_code == 2);
    }
    SECTION("unwritable output: exit 1") {
        const auto r = test::run_command(kappa_render("-o " + dir + "/no/such/dir/x.png --size 32x32"));
        CHECK(r.exit_code == 1);
        CHECK(r.output.find("x.png") != std::string::npos);
    }
    SECTION("a bad .xf file: exit 1, names the file") {
        test::write_file(dir + "/bad.xf", "1 0 0\n0 1 zero\n");
        const auto r = test::run_command(kappa_render("-o " + dir + "/x.png --xf " + dir + "/bad.xf"));
        CHECK(r.exit_code == 1);
        CHECK(r.output.find("bad.xf") != std::string::npos);
    }
}

TEST_CASE("kappa render writes JPEG for .jpg and .jpeg, and refuses other extensions before reading the mesh",
          "[render][cli]") {
    const std::string dir = test::temp_dir();
    for (const std::string name : {"a.jpg", "b.JPEG"}) {
        const auto r = test::run_command(kappa_render("-q -o " + dir + "/" + name + " --size 64x48"));
        INFO(r.output);
        REQUIRE(r.exit_code == 0);
        const std::string bytes = test::read_file(dir + "/" + name);
        REQUIRE(bytes.size() > 3);
        CHECK(uint8_t(bytes[0]) == 0xFF);  // JPEG start-of-image marker
        CHECK(uint8_t(bytes[1]) == 0xD8);
    }
    // An unknown extension, a transparent JPEG: errors naming the file, before any work.
    const auto bmp = test::run_command(kappa_render("no-such-mesh.ply -o " + dir + "/x.bmp"));
    CHECK(bmp.exit_code == 2);
    CHECK(bmp.output.find("x.bmp") != std::string::npos);
    CHECK(bmp.output.find(".png, .jpg, .jpeg, .svg or .pdf") != std::string::npos);
    CHECK(test::count_lines(bmp.output) == 1);
    const auto clear = test::run_command(kappa_render("-o " + dir + "/t.jpg --background transparent"));
    CHECK(clear.exit_code == 2);
    CHECK(clear.output.find("transparency") != std::string::npos);
    CHECK(!std::filesystem::exists(dir + "/t.jpg"));
}

TEST_CASE("kappa render checks the output folder and the size before reading the mesh", "[render][cli]") {
    // The mesh does not exist either: the message is about what is checked first.
    const auto folder = test::run_command(kappa_render("no-such-mesh.ply -o /no/such/folder/x.png"));
    CHECK(folder.exit_code == 1);
    CHECK(folder.output.find("no such folder '/no/such/folder'") != std::string::npos);
    CHECK(test::count_lines(folder.output) == 1);
    const auto size = test::run_command(kappa_render("no-such-mesh.ply -o /tmp/x.png --size 100000x100000"));
    CHECK(size.exit_code == 2);
    CHECK(size.output.find("--size 100000x100000 is too large") != std::string::npos);
}

TEST_CASE("kappa render refuses a mesh with no faces in one line naming it", "[render][cli]") {
    const std::string dir = test::temp_dir();
    test::write_file(dir + "/points.ply",
                     "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                     "element face 0\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n");
    const auto r = test::run_command(kappa_render(dir + "/points.ply -o " + dir + "/p.png"));
    CHECK(r.exit_code == 1);
    CHECK(r.output.find("points.ply: the mesh has no faces") != std::string::npos);
    CHECK(test::count_lines(r.output) == 1);
    CHECK(!std::filesystem::exists(dir + "/p.png"));
}

TEST_CASE("kappa render --view and --eye without --target frame the model from that direction", "[render][cli]") {
    const std::string dir = test::temp_dir();
    const std::string common = " -q --size 160x120 --shading none --msaa off -o " + dir;
    // --view 90,0 looks from +x; --eye on the +x axis, near or far, frames the same picture.
    REQUIRE(test::run_command(kappa_render("--view 90,0" + common + "/view.png")).exit_code == 0);
    REQUIRE(test::run_command(kappa_render("--eye 5,0,0" + common + "/near.png")).exit_code == 0);
    REQUIRE(test::run_command(kappa_render("--eye 1000,0,0" + common + "/far.png")).exit_code == 0);
    const render::Image view = render::read_png(dir + "/view.png"), near = render::read_png(dir + "/near.png"),
                        far = render::read_png(dir + "/far.png");
    // The same picture, up to where lines merged on screen (test_render_fixtures.h).
    CHECK(test::largest_difference(view, near) <= test::kScreenMergeTolerance);
    CHECK(test::largest_difference(view, far) <= test::kScreenMergeTolerance);
    CHECK(test::count_ink(view) > 100);
    // With --target the distance is the user's: from 1000 units away the model is a dot.
    REQUIRE(test::run_command(kappa_render("--eye 1000,0,0 --target 0,0,0" + common + "/dot.png")).exit_code == 0);
    CHECK(test::count_ink(render::read_png(dir + "/dot.png")) < test::count_ink(view) / 10);
    // Bad angles and conflicting options: usage errors.
    CHECK(test::run_command(kappa_render("--view 30" + common + "/x.png")).exit_code == 2);
    CHECK(test::run_command(kappa_render("--view 30,100" + common + "/x.png")).exit_code == 2);
    CHECK(test::run_command(kappa_render("--view 30,20 --eye 1,1,1" + common + "/x.png")).exit_code == 2);
}

TEST_CASE("kappa render --colorbar writes the values of the bar's ends and of zero beside it", "[render][cli]") {
    const std::string dir = test::temp_dir();
    const std::string common = " -q --size 600x300 --shading none --lines none --colormap mean -o " + dir;
    REQUIRE(test::run_command(kappa_render("--colorbar" + common + "/bar.png")).exit_code == 0);
    REQUIRE(test::run_command(kappa_render(common + "/plain.png")).exit_code == 0);
    const render::Image bar = render::read_png(dir + "/bar.png"), plain = render::read_png(dir + "/plain.png");
    // The bar is half the height, centred, at the right edge; labels sit left of it
    // (the model, framed in the middle 300 pixels, stays clear of x > 480).
    auto dark_near_row = [](const render::Image& im, int row) {
        int n = 0;
        for (int y = row - 8; y <= row + 8; ++y)
            for (int x = 480; x < 565; ++x) n += test::is_ink(im.at(x, y));
        return n;
    };
    for (int row : {75, 150, 225}) {  // top (+range), zero, bottom (-range)
        INFO("row " << row);
        CHECK(dark_near_row(bar, row) > 10);
        CHECK(dark_near_row(plain, row) == 0);
    }
}

// The bar of a signed map has a one-pixel tick at zero, whatever the size:
// at 1024x768 the middle of the bar falls between two pixel rows, where the
// tick was left out before (the row's centre was half a pixel off, give or
// take the rasteriser's rounding).
TEST_CASE("kappa render --colorbar marks zero on the bar with one row at any size", "[render][cli]") {
    const std::string dir = test::temp_dir();
    for (const glm::ivec2 size : {glm::ivec2(1024, 768), glm::ivec2(600, 300), glm::ivec2(640, 481)}) {
        const std::string png = dir + "/bar.png";
        REQUIRE(test::run_command(kappa_render("--colorbar -q --shading none --lines none --colormap mean --size " +
                                               std::to_string(size.x) + "x" + std::to_string(size.y) + " -o " + png))
                    .exit_code == 0);
        const render::Image bar = render::read_png(png);
        // The bar: 3.5% of the width wide, 3% of the smaller side from the right edge (ColorBar::draw).
        const int x = size.x - int(0.03f * float(std::min(size.x, size.y)) + 0.0175f * float(size.x));
        std::vector<int> dark;
        for (int y = size.y / 2 - 20; y <= size.y / 2 + 20; ++y)
            if (test::is_ink(bar.at(x, y))) dark.push_back(y);
        INFO(size.x << "x" << size.y << ": dark rows at x = " << x << " near the middle: " << dark.size());
        REQUIRE(dark.size() == 1);
        CHECK(std::abs(dark[0] - size.y / 2) <= 1);
    }
}

namespace {

// The unit cube as an OBJ file (two triangles a face).
std::string cube_obj() {
    return "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\n"
           "f 1 5 7\nf 1 7 3\nf 2 4 8\nf 2 8 6\nf 1 2 6\nf 1 6 5\n"
           "f 3 7 8\nf 3 8 4\nf 1 3 4\nf 1 4 2\nf 5 6 8\nf 5 8 7\n";
}

bool ink_within(const render::Image& im, glm::vec2 p, float r) {
    for (int y = int(p.y - r); y <= int(p.y + r); ++y)
        for (int x = int(p.x - r); x <= int(p.x + r); ++x)
            if (x >= 0 && y >= 0 && x < im.width && y < im.height && test::is_ink(im.at(x, y))) return true;
    return false;
}

// The unit cube's 12 edges (corners a < b differing in one coordinate, as in
// test::unit_cube), each visible when one of its two faces faces the eye.
struct CubeEdge {
    int a, b;
    glm::vec3 p, q;
    bool visible;
};
std::vector<CubeEdge> cube_edges(const Mesh& cube, const glm::vec3& eye) {
    std::vector<CubeEdge> edges;
    for (int a = 0; a < 8; ++a)
        for (int bit : {1, 2, 4}) {
            const int b = a | bit;
            if (b == a) continue;
            const glm::vec3 p = cube.positions[size_t(a)], q = cube.positions[size_t(b)];
            bool visible = false;
            for (int other : {1, 2, 4}) {  // the two faces: the other two axes, at this edge's side
                if (other == bit) continue;
                const int axis = other == 1 ? 0 : other == 2 ? 1 : 2;
                glm::vec3 n(0.0f);
                n[axis] = (a & other) ? 1.0f : -1.0f;
                visible |= glm::dot(n, eye - p) > 0;
            }
            edges.push_back({a, b, p, q, visible});
        }
    return edges;
}

}  // namespace

TEST_CASE("A cube draws every visible edge once, unbroken, and no hidden one", "[render][cli][creases]") {
    const std::string dir = test::temp_dir();
    test::write_file(dir + "/cube.obj", cube_obj());
    const auto r = test::run_command(kappa_render(dir + "/cube.obj -o " + dir + "/cube.png --size 400x300 "
                                                  "--shading none --msaa off --view 30,20"));
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    CHECK(r.output.find("12 sharp edges") != std::string::npos);
    const render::Image im = render::read_png(dir + "/cube.png");
    const Mesh cube = test::unit_cube();
    const render::BoundingSphere bounds = render::bounding_sphere(cube);
    const render::Camera camera = render::Camera::framing(bounds, 30.0f, 400.0f / 300.0f, view_direction({30, 20}));
    int visible_edges = 0;
    for (const CubeEdge& e : cube_edges(cube, camera.eye())) {
        int inked = 0, samples = 0;
        for (float t = 0.05f; t < 0.96f; t += 0.01f, ++samples)  // every pixel or so along the edge
            inked += ink_within(im, test::project(camera, bounds, glm::mix(e.p, e.q, t), 400, 300), 1.5f);
        INFO("edge " << e.a << "-" << e.b << (e.visible ? " visible" : " hidden") << ": " << inked << " of " << samples);
        if (e.visible) {
            ++visible_edges;
            CHECK(inked == samples);  // drawn all along: no gap
        } else {
            CHECK(inked < samples / 4);  // hidden: only where it crosses a visible edge
        }
    }
    CHECK(visible_edges == 9);
}

TEST_CASE("Creases change nothing on smooth meshes, and can be turned off", "[render][cli][creases]") {
    const std::string dir = test::temp_dir();
    const std::string spot = test::shared_mesh("spot.obj");
    const std::string common = " -q --size 200x150 --shading none -o " + dir;
    REQUIRE(test::run_command(kappa_render(spot + common + "/auto.png")).exit_code == 0);
    REQUIRE(test::run_command(kappa_render(spot + " --crease-angle off" + common + "/off.png")).exit_code == 0);
    const bool same = render::read_png(dir + "/auto.png").pixels == render::read_png(dir + "/off.png").pixels;
    CHECK(same);
    test::write_file(dir + "/cube.obj", cube_obj());
    const auto off = test::run_command(kappa_render(dir + "/cube.obj --crease-angle off" + common + "/c.png"));
    CHECK(off.output.find("sharp edges") == std::string::npos);
    CHECK(test::run_command(kappa_render(dir + "/cube.obj --crease-angle 200" + common + "/x.png")).exit_code == 2);
}

namespace {

// A closed cylinder around z: n segments, flat caps as fans (OBJ text).
std::string cylinder_obj(int n) {
    std::string s;
    for (int k = 0; k < 2; ++k)
        for (int i = 0; i < n; ++i) {
            const double a = 2 * M_PI * i / n;
            s += "v " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " " + std::to_string(1.5 * k) + "\n";
        }
    s += "v 0 0 0\nv 0 0 1.5\n";
    const int bottom = 2 * n + 1, top = 2 * n + 2;
    for (int i = 0; i < n; ++i) {
        const int a = i + 1, b = (i + 1) % n + 1, c = a + n, d = b + n;
        s += "f " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(d) + "\n";
        s += "f " + std::to_string(a) + " " + std::to_string(d) + " " + std::to_string(c) + "\n";
        s += "f " + std::to_string(bottom) + " " + std::to_string(b) + " " + std::to_string(a) + "\n";
        s += "f " + std::to_string(top) + " " + std::to_string(c) + " " + std::to_string(d) + "\n";
    }
    return s;
}

// Fraction of the model's outline pixels (mask pixels next to background)
// with ink within 2 px in the line drawing of the same view.
double outline_inked(const std::string& mesh, const std::string& dir, const std::string& view) {
    const std::string common = " -q --size 400x300 --msaa off " + view + " -o " + dir;
    // The mask: the shaded model on a magenta background (lit surface can be white).
    const auto a = test::run_command(kappa_render(mesh + " --lines none --background '#ff00ff'" + common + "/mask.png"));
    const auto b = test::run_command(kappa_render(mesh + " --shading none" + common + "/lines.png"));
    if (a.exit_code != 0 || b.exit_code != 0) return -1;
    const render::Image mask = render::read_png(dir + "/mask.png"), lines = render::read_png(dir + "/lines.png");
    auto object = [&](int x, int y) {
        if (x < 0 || y < 0 || x >= mask.width || y >= mask.height) return false;
        const render::Rgba c = mask.at(x, y);
        return !(c.r == 255 && c.g == 0 && c.b == 255);  // not the magenta background
    };
    size_t outline = 0, inked = 0;
    for (int y = 0; y < mask.height; ++y)
        for (int x = 0; x < mask.width; ++x) {
            if (!object(x, y) || (object(x - 1, y) && object(x + 1, y) && object(x, y - 1) && object(x, y + 1))) continue;
            ++outline;
            inked += ink_within(lines, glm::vec2(x + 0.5f, y + 0.5f), 2.0f);
        }
    return outline ? double(inked) / double(outline) : 0.0;
}

}  // namespace

TEST_CASE("Outlines are closed: every outline pixel of a cube, a cylinder and fandisk is drawn",
          "[render][cli][creases]") {
    const std::string dir = test::temp_dir();
    test::write_file(dir + "/cube.obj", cube_obj());
    test::write_file(dir + "/cylinder.obj", cylinder_obj(48));
    struct Case {
        std::string mesh, view;
        double bound;
    };
    const Case cases[] = {{dir + "/cube.obj", "", 0.995},
                          {dir + "/cylinder.obj", "", 0.995},
                          {dir + "/cylinder.obj", "--view 0,10", 0.995},
                          {test::shared_mesh("fandisk.obj"), "", 0.99}};
    for (const Case& c : cases) {
        const double f = outline_inked(c.mesh, dir, c.view);
        INFO(c.mesh << " " << c.view << ": outline pixels with ink within 2 px " << f);
        CHECK(f > c.bound);
    }
}

TEST_CASE("No suggestive contours from crease artefacts on a cube and a cylinder", "[render][cli][creases]") {
    const std::string dir = test::temp_dir();
    test::write_file(dir + "/cube.obj", cube_obj());
    test::write_file(dir + "/cylinder.obj", cylinder_obj(48));
    for (const std::string name : {"cube", "cylinder"}) {
        const std::string common = " -q --size 400x300 --shading none --lines suggestive -o " + dir;
        REQUIRE(test::run_command(kappa_render(dir + "/" + name + ".obj" + common + "/split.png")).exit_code == 0);
        REQUIRE(test::run_command(kappa_render(dir + "/" + name + ".obj --crease-angle off" + common + "/raw.png"))
                    .exit_code == 0);
        const size_t split = test::count_ink(render::read_png(dir + "/split.png"));
        const size_t raw = test::count_ink(render::read_png(dir + "/raw.png"));
        INFO(name << ": suggestive-contour ink " << split << " split at creases, " << raw << " not split");
        CHECK(split == 0);  // flat faces and a cylinder (K = 0) have none
    }
    // fandisk: curvature averaged across its sharp edges draws suggestive
    // contours along them; split, it draws well under half as many
    // (measured at 800x600: 1335 against 3144 pixels).
    const std::string fandisk = test::shared_mesh("fandisk.obj");
    const std::string common = " -q --size 800x600 --shading none --lines suggestive -o " + dir;
    REQUIRE(test::run_command(kappa_render(fandisk + common + "/f-split.png")).exit_code == 0);
    REQUIRE(test::run_command(kappa_render(fandisk + " --crease-angle off" + common + "/f-raw.png")).exit_code == 0);
    const size_t split = test::count_ink(render::read_png(dir + "/f-split.png"));
    const size_t raw = test::count_ink(render::read_png(dir + "/f-raw.png"));
    INFO("fandisk: " << split << " split, " << raw << " not split");
    CHECK(split * 10 < raw * 6);
}

TEST_CASE("A turntable turns around the model's vertical axis: a cube looks the same every quarter turn",
          "[render][cli]") {
    const std::string dir = test::temp_dir();
    test::write_file(dir + "/cube.obj", cube_obj());
    const auto r = test::run_command(
        kappa_render(dir + "/cube.obj -q --size 200x150 --shading none --msaa off --turntable 4 -o " + dir + "/t.png"));
    REQUIRE(r.exit_code == 0);
    const render::Image first = render::read_png(dir + "/t-000.png");
    for (const char* name : {"t-001.png", "t-002.png", "t-003.png"}) {
        const render::Image other = render::read_png(dir + "/" + name);
        REQUIRE(other.width == first.width);
        size_t differ = 0;
        for (int y = 0; y < first.height; ++y)
            for (int x = 0; x < first.width; ++x) differ += test::is_ink(first.at(x, y)) != test::is_ink(other.at(x, y));
        INFO(name << ": " << differ << " pixels differ in ink");
        CHECK(differ < 30);  // rounding along the edges only
    }
}

TEST_CASE("Hidden lines on: a cube draws its hidden edges dashed and light and its visible ones as before",
          "[render][cli][creases]") {
    const std::string dir = test::temp_dir();
    test::write_file(dir + "/cube.obj", cube_obj());
    const auto r = test::run_command(kappa_render(dir + "/cube.obj -o " + dir + "/h.png --size 400x300 "
                                                  "--shading none --msaa off --view 30,20 --hidden-lines on"));
    REQUIRE(r.exit_code == 0);
    const render::Image im = render::read_png(dir + "/h.png");
    const Mesh cube = test::unit_cube();
    const render::BoundingSphere bounds = render::bounding_sphere(cube);
    const render::Camera camera = render::Camera::framing(bounds, 30.0f, 400.0f / 300.0f, view_direction({30, 20}));
    // The darkest value within 1 px of a point.
    auto darkest = [&](glm::vec2 p) {
        int v = 255;
        for (int y = int(p.y) - 1; y <= int(p.y) + 1; ++y)
            for (int x = int(p.x) - 1; x <= int(p.x) + 1; ++x)
                if (x >= 0 && y >= 0 && x < im.width && y < im.height) v = std::min(v, int(im.at(x, y).r));
        return v;
    };
    for (const CubeEdge& e : cube_edges(cube, camera.eye())) {
        int black = 0, grey = 0, white = 0;
        for (float t = 0.15f; t < 0.86f; t += 0.01f) {
            const int v = darkest(test::project(camera, bounds, glm::mix(e.p, e.q, t), 400, 300));
            (v < 100 ? black : v < 230 ? grey : white)++;
        }
        INFO("edge " << e.a << "-" << e.b << ": black " << black << ", grey " << grey << ", white " << white);
        if (e.visible) {
            CHECK(white == 0);
            CHECK(black > grey);
        } else {  // dashed: light ink with gaps, never full black away from the visible edges
            CHECK(grey > 10);
            CHECK(white > 5);
        }
    }
}

TEST_CASE("Lines silhouette: the whole exterior outline and no interior contour", "[render][cli]") {
    const std::string dir = test::temp_dir();
    const std::string bunny = test::shared_mesh("bunny.ply");
    const std::string common = " -q --size 400x300 --msaa off --shading none -o " + dir;
    REQUIRE(test::run_command(kappa_render(bunny + " --lines none --background '#ff00ff' -q --size 400x300 --msaa off -o " +
                                           dir + "/mask.png")).exit_code == 0);
    REQUIRE(test::run_command(kappa_render(bunny + " --lines silhouette" + common + "/sil.png")).exit_code == 0);
    REQUIRE(test::run_command(kappa_render(bunny + " --lines contours" + common + "/con.png")).exit_code == 0);
    const render::Image mask = render::read_png(dir + "/mask.png"), sil = render::read_png(dir + "/sil.png"),
                        con = render::read_png(dir + "/con.png");
    auto object = [&](int x, int y) {
        if (x < 0 || y < 0 || x >= mask.width || y >= mask.height) return false;
        const render::Rgba c = mask.at(x, y);
        return !(c.r == 255 && c.g == 0 && c.b == 255);  // not the magenta background
    };
    auto near_background = [&](int x, int y, int r) {
        for (int dy = -r; dy <= r; ++dy)
            for (int dx = -r; dx <= r; ++dx)
                if (!object(x + dx, y + dy)) return true;
        return false;
    };
    size_t outline = 0, outline_inked = 0, ink = 0, ink_off_outline = 0;
    for (int y = 0; y < mask.height; ++y)
        for (int x = 0; x < mask.width; ++x) {
            if (test::is_ink(sil.at(x, y))) {
                ++ink;
                ink_off_outline += !near_background(x, y, 4);
            }
            if (object(x, y) && near_background(x, y, 1)) {
                ++outline;
                outline_inked += ink_within(sil, glm::vec2(x + 0.5f, y + 0.5f), 2.0f);
            }
        }
    INFO("outline " << outline << " px, inked " << outline_inked << "; silhouette ink " << ink << ", away from the "
                    "background " << ink_off_outline << "; contour ink " << test::count_ink(con));
    CHECK(double(outline_inked) > 0.98 * double(outline));  // measured 99.2%
    CHECK(ink_off_outline < ink / 100);
    CHECK(test::count_ink(con) > ink + 200);  // the interior contours (ears, legs) left out
}

TEST_CASE("kappa render --estimator colours the surface with that estimator's own fields", "[render][cli][estimators]") {
    const std::string dir = test::temp_dir();
    auto render_with = [&](const std::string& estimator) {
        const std::string out = dir + "/" + estimator + ".png";
        const auto r = test::run_command(kappa_render("-o " + out + " --size 96x96 --colormap k1 --lines none -q " +
                                                      "--detail off --estimator " + estimator));
        INFO(r.output);
        REQUIRE(r.exit_code == 0);
        return render::read_png(out);
    };
    const render::Image paper = render_with("rusinkiewicz");
    for (const char* name : {"jet", "tensor-averaging", "normal-fit", "points-normals-fit"}) {
        INFO(name);
        const render::Image other = render_with(name);
        REQUIRE(other.pixels.size() == paper.pixels.size());
        CHECK(other.pixels != paper.pixels);       // the colours come from another estimate
        CHECK(other.at(48, 48).a == 255);          // and the model is drawn
    }
    // The colours themselves: on green paper (no colour of the map is
    // green) the model's pixels decode to k1 / range in [-1, 1]
    // (shaders/common/colormap.glsl: white to red (0.80, 0.14, 0.12) for
    // positive values, white to blue (0.19, 0.34, 0.80) for negative ones).
    // Every estimator sees the same bumpy sphere: the same sign where the
    // default's value is clear, and close values (each map is scaled by its
    // own robust range, so the scale matches too).
    auto decode = [&](const std::string& estimator, std::vector<float>& value) {
        const std::string out = dir + "/green-" + estimator + ".png";
        const auto r = test::run_command(kappa_render("-o " + out + " --size 128x128 --colormap k1 --lines none "
                                                      "--shading none --background '#00ff00' -q --detail off "
                                                      "--estimator " + estimator));
        INFO(r.output);
        REQUIRE(r.exit_code == 0);
        const render::Image image = render::read_png(out);
        auto paper_at = [&](int x, int y) {
            const render::Rgba c = image.at(std::clamp(x, 0, image.width - 1), std::clamp(y, 0, image.height - 1));
            return c.g > c.r + 40 && c.g > c.b + 40;
        };
        value.assign(size_t(image.width) * size_t(image.height), NAN);
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) {
                bool edge = false;  // pixels blended with the paper at the outline are left out
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) edge |= paper_at(x + dx, y + dy);
                if (edge) continue;
                const render::Rgba c = image.at(x, y);
                value[size_t(y) * size_t(image.width) + size_t(x)] =
                    c.r >= c.b ? (255.0f - c.g) / (0.86f * 255.0f) : -(255.0f - c.r) / (0.81f * 255.0f);
            }
    };
    std::vector<float> reference;
    decode("rusinkiewicz", reference);
    size_t model = 0;
    for (float v : reference) model += !std::isnan(v);
    REQUIRE(model > 128 * 128 / 4);  // the model fills the middle of the picture
    for (const char* name : {"jet", "tensor-averaging", "normal-fit", "points-normals-fit"}) {
        std::vector<float> value;
        decode(name, value);
        size_t both = 0, clear = 0, same_sign = 0;
        double difference = 0;
        for (size_t i = 0; i < value.size(); ++i) {
            if (std::isnan(value[i]) || std::isnan(reference[i])) continue;
            ++both;
            difference += std::fabs(value[i] - reference[i]);
            if (std::fabs(reference[i]) > 0.25f) ++clear, same_sign += (value[i] > 0) == (reference[i] > 0);
        }
        INFO(name << ": " << both << " model pixels in both, " << clear << " with |k1| / range > 0.25, "
                  << same_sign << " of those of the same sign; mean |difference| " << difference / double(both));
        CHECK(both > model * 9 / 10);
        CHECK(clear > both / 4);
        CHECK(same_sign > clear * 97 / 100);
        CHECK(difference / double(both) < 0.02);  // measured 0.0016 to 0.0039 (2026-11-26)
    }
    const auto bad = test::run_command(kappa_render("-o " + dir + "/x.png --estimator cgal"));
    CHECK(bad.exit_code == 2);
    CHECK(test::count_lines(bad.output) == 1);
}

namespace {

// Both ways: the fraction of each drawing's ink within 1.5 px of the other's (the smaller).
double ink_agreement(const render::Image& a, const render::Image& b) {
    return std::min(render::ink_within(a, b, 1.5f), render::ink_within(b, a, 1.5f));
}

}  // namespace

TEST_CASE("A turntable's frame i is the view at azimuth + 360 i / N, about the model's y axis",
          "[render][cli][turntable]") {
    // The bunny looks different from every side, unlike a cube: a wrong
    // axis, direction or step fails. Frame i of --turntable 4 --view 30,20
    // must match --view (30 + 90 i),20 (azimuth: degrees about +y, 0 = from
    // +z, 90 = from +x), and not the view turned the other way.
    const std::string dir = test::temp_dir(), bunny = test::shared_mesh("bunny.ply");
    const std::string common = " -q --size 160x120 --shading none --msaa off";
    REQUIRE(test::run_command(kappa_render(bunny + common + " --view 30,20 --turntable 4 -o " + dir + "/t.png"))
                .exit_code == 0);
    for (int i = 1; i < 4; ++i) {
        const std::string az = std::to_string(30 + 90 * i), wrong = std::to_string(30 - 90 * i);
        REQUIRE(test::run_command(kappa_render(bunny + common + " --view " + az + ",20 -o " + dir + "/v.png"))
                    .exit_code == 0);
        REQUIRE(test::run_command(kappa_render(bunny + common + " --view " + wrong + ",20 -o " + dir + "/w.png"))
                    .exit_code == 0);
        const render::Image frame = render::read_png(dir + "/t-00" + std::to_string(i) + ".png");
        const double same = ink_agreement(frame, render::read_png(dir + "/v.png"));
        const double other = ink_agreement(frame, render::read_png(dir + "/w.png"));
        INFO("frame " << i << ": agreement with --view " << az << ",20: " << same << ", with --view " << wrong
                      << ",20: " << other);
        CHECK(test::count_ink(frame) > 300);
        CHECK(same > 0.98);
        if (i != 2) CHECK(other < 0.8);  // (half a turn is the same both ways)
    }
}

TEST_CASE("A turntable with --light-frame model keeps the light on the model as it turns", "[render][cli][turntable]") {
    // With the light fixed to the model, frame i of --turntable 4 --view 30,20
    // is the single view at azimuth 30 + 90 i lit from the same model
    // direction; lit from the camera instead (the default), the shading of
    // that view differs.
    const std::string dir = test::temp_dir(), bunny = test::shared_mesh("bunny.ply");
    const std::string common = " -q --size 160x120 --lines none --msaa off --shading lambert";
    REQUIRE(test::run_command(kappa_render(bunny + common + " --light-frame model --view 30,20 --turntable 4 -o " + dir +
                                           "/t.png"))
                .exit_code == 0);
    auto mean_difference = [](const render::Image& a, const render::Image& b) {
        double sum = 0;
        for (size_t i = 0; i < a.pixels.size(); ++i) sum += std::abs(int(a.pixels[i]) - int(b.pixels[i]));
        return sum / double(a.pixels.size());
    };
    for (int i = 1; i < 4; ++i) {
        const std::string az = std::to_string(30 + 90 * i);
        REQUIRE(test::run_command(kappa_render(bunny + common + " --light-frame model --view " + az + ",20 -o " + dir +
                                               "/model.png"))
                    .exit_code == 0);
        REQUIRE(test::run_command(kappa_render(bunny + common + " --view " + az + ",20 -o " + dir + "/camera.png"))
                    .exit_code == 0);
        const render::Image frame = render::read_png(dir + "/t-00" + std::to_string(i) + ".png");
        const double same = mean_difference(frame, render::read_png(dir + "/model.png"));
        const double camera_lit = mean_difference(frame, render::read_png(dir + "/camera.png"));
        INFO("frame " << i << ": mean difference from the model-lit view " << same << ", from the camera-lit one "
                      << camera_lit);
        CHECK(same < 0.5);
        CHECK(camera_lit > 2.0);
    }
}

TEST_CASE("A turntable with --up or --xf turns about the camera's up axis, through the target or the model's centre",
          "[render][cli][turntable]") {
    // Camera at E looking at T with up U (perpendicular to E - T): a quarter
    // turn moves the eye to T + rot(U, 90 deg) (E - T). The same view as an
    // rtsc .xf file turns about the same axis through the bounding sphere's centre.
    const std::string dir = test::temp_dir(), bunny = test::shared_mesh("bunny.ply");
    const std::string common = " -q --size 160x120 --shading none --msaa off --fov 30";
    const render::BoundingSphere bounds = render::bounding_sphere(load_mesh(bunny));
    const glm::vec3 T = bounds.center, U = glm::normalize(glm::vec3(0.3f, 1.0f, 0.2f));
    const glm::vec3 side = glm::normalize(glm::cross(U, glm::vec3(0, 0, 1)));
    const glm::vec3 E = T + 4.0f * bounds.radius * glm::normalize(glm::cross(side, U));  // perpendicular to U
    const glm::vec3 E1 = T + glm::vec3(glm::rotate(glm::mat4(1), float(M_PI / 2), U) * glm::vec4(E - T, 0));
    const glm::vec3 wrong = T + glm::vec3(glm::rotate(glm::mat4(1), -float(M_PI / 2), U) * glm::vec4(E - T, 0));
    auto vec = [](glm::vec3 v) {
        char s[128];
        std::snprintf(s, sizeof s, "%.9g,%.9g,%.9g", v.x, v.y, v.z);
        return std::string(s);
    };
    auto camera_args = [&](glm::vec3 eye) { return " --eye " + vec(eye) + " --target " + vec(T) + " --up " + vec(U); };
    render::write_xf(dir + "/view.xf", glm::lookAt(E, T, U));
    REQUIRE(test::run_command(kappa_render(bunny + common + camera_args(E) + " --turntable 4 -o " + dir + "/u.png"))
                .exit_code == 0);
    REQUIRE(test::run_command(kappa_render(bunny + common + " --xf " + dir + "/view.xf --turntable 4 -o " + dir +
                                           "/x.png"))
                .exit_code == 0);
    REQUIRE(test::run_command(kappa_render(bunny + common + camera_args(E1) + " -o " + dir + "/e1.png")).exit_code == 0);
    REQUIRE(test::run_command(kappa_render(bunny + common + camera_args(wrong) + " -o " + dir + "/w.png")).exit_code == 0);
    const render::Image expected = render::read_png(dir + "/e1.png"), other = render::read_png(dir + "/w.png");
    REQUIRE(test::count_ink(expected) > 300);
    for (const char* frame : {"u-001.png", "x-001.png"}) {
        const render::Image image = render::read_png(dir + "/" + frame);
        const double same = ink_agreement(image, expected), turned_back = ink_agreement(image, other);
        INFO(frame << ": agreement with the eye turned a quarter about the up axis " << same
                   << ", turned the other way " << turned_back);
        CHECK(same > 0.98);
        CHECK(turned_back < 0.8);
    }
}
