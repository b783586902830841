// The browser page (web/, docs/web.md) in headless Chromium, driven by
// tests/web/page_driver.py over the DevTools protocol, against the kappa
// executable: the same views draw the same lines, a bad file shows the
// command line's error and the page then opens the next mesh, and the page's
// SVG holds the CLI's strokes. Built and run only where emscripten and
// Chromium are installed (KAPPA_WEB, CMakeLists.txt).
#include "test_support.h"

#include "geometry/io/mesh_io.h"
#include "geometry/mesh/subdivide.h"
#include "render/image/ink_agreement.h"
#include "render/image/png_writer.h"

#include <catch2/catch.hpp>

#include <glm/common.hpp>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

using namespace kappa;
namespace fs = std::filesystem;

namespace {

// A folder of meshes for the page's server: the shared ones named, linked.
std::string mesh_folder(const std::vector<std::string>& names) {
    const std::string dir = test::temp_dir() + "/meshes";
    fs::create_directories(dir);
    for (const std::string& name : names) fs::create_symlink(test::shared_mesh(name), dir + "/" + name);
    return dir;
}

// A mesh as a binary PLY of positions and triangles.
void write_binary_ply(const Mesh& mesh, const std::string& path) {
    std::ofstream f(path, std::ios::binary);
    f << "ply\nformat binary_little_endian 1.0\nelement vertex " << mesh.vertex_count()
      << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << mesh.face_count()
      << "\nproperty list uchar int vertex_indices\nend_header\n";
    f.write(reinterpret_cast<const char*>(mesh.positions.data()), std::streamsize(mesh.positions.size() * 12));
    for (const Face& t : mesh.faces) {
        const unsigned char n = 3;
        const int32_t corners[3] = {int32_t(t[0]), int32_t(t[1]), int32_t(t[2])};
        f.write(reinterpret_cast<const char*>(&n), 1);
        f.write(reinterpret_cast<const char*>(corners), 12);
    }
    REQUIRE(f.good());
}

// Runs the page driver; fails the test with its output when it fails.
std::string drive_page(const std::string& meshes, const std::string& out, const std::string& actions) {
    const test::CommandResult r = test::run_command(std::string("python3 ") + KAPPA_SOURCE_DIR +
                                                    "/tests/web/page_driver.py " + KAPPA_WEB_SITE + " " + meshes +
                                                    " " + out + " " + actions);
    INFO(r.output);
    REQUIRE(r.exit_code == 0);
    return r.output;
}

std::string cli(const std::string& args) { return std::string(KAPPA_EXE) + " " + args; }

// `mesh` as dir/NAME.gltf with its positions and triangles in an external
// buffer named by `uri`, written to dir/FILE (the uri decoded; it may lie in a folder).
void write_gltf(const Mesh& mesh, const std::string& dir, const std::string& name, const std::string& uri,
                const std::string& file) {
    const size_t vertex_bytes = mesh.positions.size() * sizeof(glm::vec3), face_bytes = mesh.faces.size() * sizeof(Face);
    std::string bytes(reinterpret_cast<const char*>(mesh.positions.data()), vertex_bytes);
    bytes.append(reinterpret_cast<const char*>(mesh.faces.data()), face_bytes);
    glm::vec3 lo = mesh.positions[0], hi = lo;
    for (const glm::vec3& p : mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    std::ostringstream j;
    j << R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}], )"
      << R"("meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}], )"
      << R"("buffers": [{"byteLength": )" << bytes.size() << R"(, "uri": ")" << uri << R"("}], )"
      << R"("bufferViews": [{"buffer": 0, "byteLength": )" << vertex_bytes << R"(}, {"buffer": 0, "byteOffset": )"
      << vertex_bytes << R"(, "byteLength": )" << face_bytes << "}], "
      << R"("accessors": [{"bufferView": 0, "componentType": 5126, "type": "VEC3", "count": )"
      << mesh.positions.size() << R"(, "min": [)" << lo.x << ", " << lo.y << ", " << lo.z << R"(], "max": [)"
      << hi.x << ", " << hi.y << ", " << hi.z << "]}, "
      << R"({"bufferView": 1, "componentType": 5125, "type": "SCALAR", "count": )" << 3 * mesh.faces.size()
      << "}]}";
    test::write_file(dir + "/" + name + ".gltf", j.str());
    fs::create_directories(fs::path(dir + "/" + file).parent_path());
    test::write_file(dir + "/" + file, bytes);
}

// What each picture's ink has within 2 px of the other's, both at least 0.95.
void check_same_drawing(const std::string& page_png, const std::string& cli_png) {
    const render::Image page = render::read_png(page_png), cli_image = render::read_png(cli_png);
    const double page_in_cli = render::ink_within(page, cli_image, 2.0f);
    const double cli_in_page = render::ink_within(cli_image, page, 2.0f);
    INFO(page_png << ": ink " << render::count_ink(page) << " (page), " << render::count_ink(cli_image)
                  << " (CLI); page within 2 px of the CLI's " << page_in_cli
                  << ", the CLI's within 2 px of the page's " << cli_in_page);
    CHECK(page.width == cli_image.width);
    CHECK(page.height == cli_image.height);
    CHECK(render::count_ink(page) > 2000);
    CHECK(page_in_cli >= 0.95);
    CHECK(cli_in_page >= 0.95);
}

}  // namespace

// The issue's views: 800x600 at azimuth 30, elevation 20, the default
// settings. The page draws the lines the CPU extracts, as quads on WebGL2;
// kappa render on llvmpipe rasterises the same segments on the CPU: at least
// 0.95 of each picture's ink lies within 2 px of the other's.
TEST_CASE("the page draws what kappa render draws for the same view", "[web]") {
    const std::vector<std::string> meshes = {"bunny.ply", "fandisk.obj", "spot.obj"};
    const std::string out = test::temp_dir();
    std::string actions;
    for (const std::string& m : meshes)
        actions += " shot:" + m + ":mesh=meshes/" + m + "\\&view=30,20\\&size=800x600\\&panel=off";
    drive_page(mesh_folder(meshes), out, actions);
    for (const std::string& m : meshes) {
        const test::CommandResult r =
            test::run_command(cli("render " + test::shared_mesh(m) + " --view 30,20 --size 800x600 -q -o " + out +
                                  "/" + m + ".cli.png"));
        REQUIRE(r.exit_code == 0);
        const render::Image page = render::read_png(out + "/" + m + ".png");
        const render::Image cli_image = render::read_png(out + "/" + m + ".cli.png");
        REQUIRE(page.width == 800);
        REQUIRE(page.height == 600);
        const double page_in_cli = render::ink_within(page, cli_image, 2.0f);
        const double cli_in_page = render::ink_within(cli_image, page, 2.0f);
        INFO(m << ": ink " << render::count_ink(page) << " (page), " << render::count_ink(cli_image)
               << " (CLI); page within 2 px of the CLI's " << page_in_cli << ", the CLI's within 2 px of the page's "
               << cli_in_page);
        CHECK(render::count_ink(page) > 2000);
        CHECK(page_in_cli >= 0.95);
        CHECK(cli_in_page >= 0.95);
    }
}

// Settings beyond the lines, as kappa render draws them (any appearance
// setting is a URL parameter):
// - the colour bar of a curvature map: its labels (the command line's font,
//   baked into the page: render/compose/font_atlas.h) and its zero tick,
//   compared pixel for pixel left of the bar, where the labels are, and on the
//   bar's middle column (frame, tick, colours within a few levels: SwiftShader
//   and llvmpipe round the gradient differently);
// - streamline hatching: the strokes where the CLI's are and as much ink (the
//   page drew none before it had the surface's depth for its seeds, then
//   strokes at the line width: a third more ink).
TEST_CASE("the page draws a colour map's bar and hatching as kappa render does", "[web]") {
    const std::string out = test::temp_dir();
    const std::string view = "\\&view=30,20\\&size=800x600\\&panel=off";
    drive_page(mesh_folder({"spot.obj"}), out,
               "shot:bar:mesh=meshes/spot.obj" + view + "\\&colormap=mean\\&colorbar=on shot:hatching:mesh=meshes/spot.obj" +
                   view + "\\&hatching=cross");
    REQUIRE(test::run_command(cli("render " + test::shared_mesh("spot.obj") +
                                  " --view 30,20 --size 800x600 --hatching cross -q -o " + out + "/cli-hatching.png"))
                .exit_code == 0);
    check_same_drawing(out + "/hatching.png", out + "/cli-hatching.png");
    const double page_ink = double(render::count_ink(render::read_png(out + "/hatching.png")));
    const double cli_ink = double(render::count_ink(render::read_png(out + "/cli-hatching.png")));
    INFO("hatching ink: page " << page_ink << ", CLI " << cli_ink);
    CHECK(std::abs(page_ink - cli_ink) <= 0.05 * cli_ink);

    REQUIRE(test::run_command(cli("render " + test::shared_mesh("spot.obj") +
                                  " --view 30,20 --size 800x600 --colormap mean --colorbar -q -o " + out + "/cli.png"))
                .exit_code == 0);
    const render::Image page = render::read_png(out + "/bar.png"), ours = render::read_png(out + "/cli.png");
    REQUIRE(page.width == ours.width);
    REQUIRE(page.height == ours.height);
    // The bar: 28 px wide from x = 754, rows 150 to 449 (ColorBar::draw at 800x600); labels left of it.
    auto dark = [](render::Rgba c) { return c.r + c.g + c.b < 3 * 128; };
    size_t label_ink = 0, differing = 0, column_off = 0;
    for (int y = 130; y < 470; ++y) {
        for (int x = 690; x < 752; ++x) {
            label_ink += dark(ours.at(x, y));
            differing += dark(page.at(x, y)) != dark(ours.at(x, y));
        }
        const render::Rgba a = page.at(768, y), b = ours.at(768, y);
        column_off += std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)}) > 8;
    }
    INFO("label pixels " << label_ink << " (CLI), " << differing << " differ; " << column_off
                         << " pixels of the bar's middle column differ by more than 8 levels");
    CHECK(label_ink > 60);  // three numbers
    CHECK(differing == 0);
    CHECK(column_off == 0);
}

// With --detail the fields follow the view's scale: when the view rests
// after a zoom, the page prepares them again, in slices of about 12 ms of
// work each with the page free in between (web/page/kappa-page.js), not in
// one block that freezes it. Zoomed in and back out, the drawing is kappa
// render's again. The mesh: bunny subdivided once (278k faces), so that
// each preparation is several slices' work however fast the machine (with
// bunny itself, zooming back out, which blends the levels' values kept from
// the first view, had become 39-69 ms of work since the scale space's
// clusters run along a Z-order curve, and a fresh CI machine once cut it
// into 3 slices), and so that the first view's clustering outlasts a slice
// (tests/test_render_sliced_preparation.cpp: the page never left
// "loading" on such a mesh). Measured 2026-11-27 on the 2-core machine:
// zooming in 23 slices, the longest 46 ms of 367 ms of work; back out 14
// slices, the longest 36 ms of 203 ms. Opening the mesh is cut too, into the
// steps of MeshDrawing::open_step, ahead of the first view's slices: 43
// slices, the longest 210 ms of 1.4 s (before, one task did all of the opening).
TEST_CASE("the page prepares a new view's fields in slices and then draws what kappa render draws", "[web]") {
    const std::string meshes = mesh_folder({}), out = test::temp_dir();
    write_binary_ply(subdivide_at_midpoints(load_mesh(test::shared_mesh("bunny.ply"))), meshes + "/bunny-x4.ply");
    drive_page(meshes, out, "zoom:bunny:mesh=meshes/bunny-x4.ply\\&view=30,20\\&size=800x600\\&panel=off:6");
    const std::string json = test::read_file(out + "/bunny.json");
    // [{"zoom": "open", "preparation": {"slices": N, "longest_ms": X, "work_ms": Y, ...}, ...}, ...]
    const std::regex record("\"slices\": (\\d+), \"longest_ms\": ([0-9.e+-]+), \"work_ms\": ([0-9.e+-]+)");
    size_t preparations = 0;
    for (auto it = std::sregex_iterator(json.begin(), json.end(), record); it != std::sregex_iterator(); ++it) {
        const int slices = std::stoi((*it)[1]);
        const double longest = std::stod((*it)[2]), work = std::stod((*it)[3]);
        INFO("preparation " << preparations << ": " << slices << " slices, the longest " << longest << " ms of "
                            << work << " ms");
        // Cut, with no slice holding half the work. The first opens the mesh too, a step at a time
        // (MeshDrawing::open_step: the preparation and split, the fields, the scale space), then its
        // view's fields. No bound in milliseconds: a busy machine stretches any slice (a fresh CI
        // machine running two browsers at once: 1.4 s of work for a later view, one slice 195 ms).
        CHECK(slices >= 4);
        CHECK(longest <= 0.5 * work);
        ++preparations;
    }
    INFO(json);
    CHECK(preparations == 3);  // opened, zoomed in, then back out

    REQUIRE(test::run_command(cli("render " + meshes + "/bunny-x4.ply --view 30,20 --size 800x600 -q -o " + out +
                                  "/cli.png"))
                .exit_code == 0);
    const render::Image page = render::read_png(out + "/bunny.png"), cli_image = render::read_png(out + "/cli.png");
    INFO("the page, zoomed in and out, within 2 px of the CLI's " << render::ink_within(page, cli_image, 2.0f)
                                                                 << ", and back " << render::ink_within(cli_image, page, 2.0f));
    CHECK(render::count_ink(page) > 2000);
    CHECK(render::ink_within(page, cli_image, 2.0f) >= 0.95);
    CHECK(render::ink_within(cli_image, page, 2.0f) >= 0.95);
}

// glTF with external buffers (.gltf + .bin), in the three ways the page
// opens files: ?mesh=URL fetches the buffers its URIs name (here in a
// folder, the name percent-encoded); the file picker and drag and drop take
// them picked or dropped together. A buffer that is missing gives the CLI's
// line in the title and on the page, and the page then opens the next one.
// Each drawn as kappa render draws the same .gltf.
TEST_CASE("the page opens glTF files with external buffers from URLs and from picked and dropped files", "[web]") {
    const std::string meshes = mesh_folder({});
    const Mesh spot = load_mesh(test::shared_mesh("spot.obj"));
    write_gltf(spot, meshes, "spot", "buffers/spot%20data.bin", "buffers/spot data.bin");
    write_gltf(spot, meshes, "flat", "flat.bin", "flat.bin");
    write_gltf(spot, meshes, "broken", "missing.bin", "missing.bin");
    fs::remove(meshes + "/missing.bin");
    const std::string out = test::temp_dir(), query = "\\&view=30,20\\&size=800x600\\&panel=off";
    drive_page(meshes, out,
               "shot:url:mesh=meshes/spot.gltf" + query + " error:bad:mesh=meshes/broken.gltf" + query + ":" +
                   meshes + "/flat.gltf," + meshes + "/flat.bin drop:drop:view=30,20\\&size=800x600\\&panel=off:" +
                   meshes + "/flat.gltf," + meshes + "/flat.bin");

    const test::CommandResult r =
        test::run_command("cd " + meshes + " && " + cli("render broken.gltf -q -o " + out + "/x.png"));
    REQUIRE(r.exit_code != 0);
    const std::string cli_line = r.output.substr(0, r.output.find('\n'));  // "kappa: broken.gltf: glTF: ..."
    REQUIRE(cli_line.rfind("kappa: broken.gltf: ", 0) == 0);
    const std::string seen = test::read_file(out + "/bad.txt");
    INFO("CLI: " << cli_line << "\npage (title, message): " << seen);
    CHECK(seen == "kappa: error: " + cli_line.substr(std::string("kappa: ").size()) + "\n" + cli_line + "\n");

    REQUIRE(test::run_command(cli("render " + meshes + "/spot.gltf --view 30,20 --size 800x600 -q -o " + out +
                                  "/cli.png"))
                .exit_code == 0);
    for (const char* shot : {"url", "bad", "drop"}) check_same_drawing(out + "/" + shot + ".png", out + "/cli.png");
}

// A PLY cut in the middle of its faces: the page shows the line `kappa
// render` prints, says so in its title, and then opens the next mesh, picked
// with its file picker.
TEST_CASE("a truncated PLY shows the CLI's error and the page opens the next mesh", "[web]") {
    const std::string meshes = mesh_folder({"spot.obj"});
    const std::string bytes = test::read_file(test::shared_mesh("bunny.ply"));
    test::write_file(meshes + "/truncated.ply", bytes.substr(0, bytes.size() * 3 / 4));
    const std::string out = test::temp_dir();
    drive_page(meshes, out,
               "error:bad:mesh=meshes/truncated.ply\\&size=400x300\\&panel=off:" + test::shared_mesh("spot.obj"));

    const test::CommandResult r =
        test::run_command("cd " + meshes + " && " + cli("render truncated.ply -q -o " + out + "/x.png"));
    REQUIRE(r.exit_code != 0);
    const std::string cli_line = r.output.substr(0, r.output.find('\n'));  // "kappa: truncated.ply: ..."
    REQUIRE(cli_line.rfind("kappa: truncated.ply: ", 0) == 0);
    const std::string seen = test::read_file(out + "/bad.txt");  // the title, then the message shown
    const std::string title = seen.substr(0, seen.find('\n'));
    const std::string shown = seen.substr(seen.find('\n') + 1, seen.size() - seen.find('\n') - 2);
    INFO("CLI: " << cli_line << "\npage title: " << title << "\npage: " << shown);
    CHECK(shown == cli_line);
    CHECK(title == "kappa: error: " + cli_line.substr(std::string("kappa: ").size()));
    // Then spot drawn: lines on the canvas.
    const render::Image next = render::read_png(out + "/bad.png");
    CHECK(render::count_ink(next) > 500);
}

// The page's SVG comes from the CLI's writer: the same layers, about as
// many paths, and the strokes in the same places (both drawn by rsvg-convert:
// at least 0.95 of each one's ink within 2 px of the other's).
TEST_CASE("the page's SVG is the CLI's SVG of the same view", "[web]") {
    const std::string out = test::temp_dir();
    drive_page(mesh_folder({"spot.obj"}), out,
               "svg:spot:mesh=meshes/spot.obj\\&view=30,20\\&size=640x480\\&panel=off\\&shading=none");
    REQUIRE(test::run_command(cli("render " + test::shared_mesh("spot.obj") +
                                  " --view 30,20 --size 640x480 --shading none -q -o " + out + "/cli.svg"))
                .exit_code == 0);
    const std::string page = test::read_file(out + "/spot.svg"), ours = test::read_file(out + "/cli.svg");
    auto layers = [](const std::string& svg) {
        std::vector<std::string> ids;
        const std::regex id("<g [^>]*id=\"([a-z-]+)\"");
        for (auto it = std::sregex_iterator(svg.begin(), svg.end(), id); it != std::sregex_iterator(); ++it)
            ids.push_back((*it)[1]);
        return ids;
    };
    auto paths = [](const std::string& svg) {
        size_t n = 0;
        for (size_t at = svg.find("<path"); at != std::string::npos; at = svg.find("<path", at + 1)) ++n;
        return n;
    };
    INFO("paths: page " << paths(page) << ", CLI " << paths(ours));
    CHECK(layers(page) == layers(ours));
    CHECK(!layers(page).empty());
    CHECK(std::abs(double(paths(page)) - double(paths(ours))) <= 0.05 * double(paths(ours)) + 2);
    for (const char* name : {"spot", "cli"})
        REQUIRE(test::run_command(std::string("rsvg-convert -b white -o ") + out + "/" + name + ".svg.png " + out +
                                  "/" + name + ".svg")
                    .exit_code == 0);
    const render::Image a = render::read_png(out + "/spot.svg.png"), b = render::read_png(out + "/cli.svg.png");
    INFO("page's SVG within 2 px of the CLI's " << render::ink_within(a, b, 2.0f) << ", and back "
                                                << render::ink_within(b, a, 2.0f));
    CHECK(render::count_ink(a) > 1000);
    CHECK(render::ink_within(a, b, 2.0f) >= 0.95);
    CHECK(render::ink_within(b, a, 2.0f) >= 0.95);
}
