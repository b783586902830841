// `kappa view [MESH]`: the interactive viewer (app/viewer/). It draws with
// the same renderer and settings as `kappa render`, so every appearance
// option of `kappa render` is accepted here too and a view saved as .xf
// renders identically headless. --frames/--screenshot/--script make scripted
// runs for tests (under xvfb-run).
#include "appearance_settings.h"
#include "cli_options.h"
#include "commands.h"
#include "heap_tuning.h"

#include "app/viewer/input_script.h"
#include "app/viewer/shortcuts.h"
#include "app/viewer/view_state.h"
#include "app/viewer/viewer_app.h"
#include "render/gl/egl_context.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace kappa::app {

namespace {

// The keyboard shortcuts (the help window's table), for --help.
std::string keys_help() {
    std::string text = "Keys:\n";
    for (const viewer::Shortcut& k : viewer::shortcuts()) {
        std::string name = k.name;
        name.resize(std::max<size_t>(name.size(), 8), ' ');
        text += "  " + name + " " + k.description + "\n";
    }
    return text;
}

}  // namespace

int run_view(int argc, char** argv) {
    keep_large_blocks();  // views reuse the last view's memory (app/heap_tuning.h)
    viewer::ViewerOptions o;
    bool no_panel = false;
    std::string script_path;
    cli::Parser p("view", "[MESH] [options]",
                  "Open a mesh in a window (GLFW, OpenGL 3.3) with a panel for every setting of 'kappa render'. "
                  "Left drag orbits, right or middle drag pans, the wheel zooms toward the cursor; F1 lists the "
                  "keyboard shortcuts.");
    p.positional("MESH", o.mesh_path, "mesh file (.ply .obj .off .stl .gltf .glb); default: the built-in model", false)
        .size("--size", o.size, "window size (default 1280x800)")
        .text("--xf", o.xf_path, "start from this trimesh2/rtsc viewpoint file; Ctrl+S saves the view there",
              "FILE")
        .flag("--no-panel", no_panel, "start with the panel hidden (Tab shows it)");
    // Appearance: the options of `kappa render` from the same table
    // (app/appearance_settings.h); then the smoothing widths.
    for (const AppearanceSetting& a : appearance_settings()) {
        if (a.flag) {
            p.flag("--" + a.name, o.state.settings.*a.flag, a.help);
            continue;
        }
        p.option("--" + a.name, a.metavar, a.help, [&o, &a](const std::string& v) { return a.set(o.state.settings, v); },
                 a.expects);
    }
    p.smoothing(o.state.smoothing);
    p.integer("--frames", o.frames, "draw N frames, save --screenshot, exit (scripted runs)", 1, 1000000)
        .text("--screenshot", o.screenshot, "PNG of the whole window, panel included, after --frames", "OUT.png")
        .text("--script", script_path,
              "synthetic input, one step a line: frames N, drag X0 Y0 X1 Y1, scroll X Y N, key K, set NAME "
              "VALUE, screenshot PATH, ... (docs/viewer.md)", "FILE")
        .threads()
        .epilog(keys_help() +
                "Without a display (no X server) it exits with status 1: use 'kappa render' to render headless.\n"
                "Examples:\n"
                "  kappa view bunny.ply --detail off   (the raw 1-ring lines)\n"
                "  kappa view --shading none --lines contours,suggestive\n"
                "  xvfb-run -a -s -noreset kappa view bunny.ply --size 640x480 --frames 3 --screenshot shot.png\n");
    if (auto status = p.parse(argc, argv)) return *status;
    if (!o.screenshot.empty() && o.frames == 0) o.frames = 2;  // the panel is laid out on the first frame
    o.show_panel = !no_panel;
    if (!script_path.empty()) {
        try {
            o.script = viewer::read_script(script_path);
        } catch (const std::exception& e) {
            return cli::fail(std::string("view: ") + e.what());
        }
        if (o.script.empty() && o.frames == 0) o.frames = 1;
    }

    // Debian's GLFW is X11 only: say so in one line rather than fail later.
    const char* display = std::getenv("DISPLAY");
    if (!display || !*display) {
        std::fprintf(stderr, "kappa view: no display (DISPLAY is not set); use 'kappa render' to render headless\n");
        return 1;
    }
    try {
        viewer::ViewerApp app(std::move(o));
        return app.run();
    } catch (const render::ContextError& e) {
        std::fprintf(stderr, "kappa view: %s\n", e.what());
        return 1;
    }
}

}  // namespace kappa::app
