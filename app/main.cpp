// kappa: curvature estimation and line drawings on triangle meshes.
// Dispatches to the subcommands listed in kCommands (see app/commands.h).
#include "cli_options.h"
#include "commands.h"

#include "geometry/parallel/parallel.h"

#include <cstring>
#include <exception>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#ifndef KAPPA_VERSION
#define KAPPA_VERSION "0.1"
#endif

namespace {

using kappa::cli::UsageError;

struct Command {
    const char* name;
    const char* summary;  // one line for `kappa --help`
    int (*run)(int argc, char** argv);
};

// One line per subcommand, in the order `kappa --help` lists them.
const Command kCommands[] = {
    {"view", "open a mesh in an interactive window with a panel for every rendering setting", kappa::app::run_view},
    {"render", "draw contours, suggestive contours, shading, colour maps, hatching to a PNG (headless)",
     kappa::app::run_render},
    {"curvature", "estimate normals, curvature and its derivative per vertex; write CSV or PLY",
     kappa::app::run_curvature},
    {"info", "print mesh statistics: counts, bounds, edges, boundaries, components", kappa::app::run_info},
    {"batch", "render and compute for many meshes and views from a manifest (--shard I/N, skips existing outputs)",
     kappa::app::run_batch},
};

std::vector<std::string> command_names() {
    std::vector<std::string> names;
    for (const auto& c : kCommands) names.push_back(c.name);
    return names;
}

const Command* find_command(const std::string& name) {
    for (const auto& c : kCommands)
        if (name == c.name) return &c;
    return nullptr;
}

std::string main_help() {
    std::string out =
        "Usage: kappa [--threads N] COMMAND [ARGS...]\n"
        "\n"
        "Curvature (Rusinkiewicz 2004) and line drawings (suggestive contours) on\n"
        "triangle meshes. Without a MESH argument, commands use the built-in model.\n"
        "\nCommands:\n";
    for (const auto& c : kCommands) out += "  " + std::string(c.name) + std::string(12 - std::strlen(c.name), ' ') + c.summary + "\n";
    out +=
        "\nOptions:\n"
        "  --threads N  worker threads for every command that computes (default: all cores)\n"
        "  --version    print the version and exit\n"
        "  -h, --help   show this help and exit\n"
        "\nRun 'kappa COMMAND --help' for the options of a command.\n";
    return out;
}

UsageError unknown_command(const std::string& name) {
    std::string guess = kappa::cli::closest_match(name, command_names());
    return UsageError("kappa: unknown command '" + name + "'" +
                      (guess.empty() ? "" : "; did you mean '" + guess + "'?") +
                      " (commands: " + kappa::cli::join(command_names(), ", ") + "; see 'kappa --help')");
}

int dispatch(int argc, char** argv) {
    int i = 1;
    // Global options before the command name.
    for (; i < argc && argv[i][0] == '-'; ++i) {
        const std::string arg = argv[i];
        if (arg == "-h" || arg == "--help") {
            std::cout << main_help();
            return 0;
        }
        if (arg == "--version") {
            std::cout << "kappa " << KAPPA_VERSION << "\n";
            return 0;
        }
        if (arg == "--threads" || arg.rfind("--threads=", 0) == 0) {
            std::string value = arg.size() > 9 ? arg.substr(10) : (i + 1 < argc ? argv[++i] : "");
            auto n = kappa::cli::parse_int(value);
            if (!n || *n < 0 || *n > 4096)
                throw UsageError("kappa: --threads expects an integer in [0, 4096], got '" + value + "'");
            kappa::set_thread_count(unsigned(*n));
            continue;
        }
        std::string guess = kappa::cli::closest_match(arg, {"--help", "--version", "--threads"});
        throw UsageError("kappa: unknown option '" + arg + "'" +
                         (guess.empty() ? "" : "; did you mean '" + guess + "'?") + " (see 'kappa --help')");
    }
    if (i >= argc) {
        std::cerr << main_help();
        return 2;
    }
    const std::string name = argv[i];
    if (name == "help") {  // `kappa help [COMMAND]`
        if (i + 1 >= argc) {
            std::cout << main_help();
            return 0;
        }
        const Command* c = find_command(argv[i + 1]);
        if (!c) throw unknown_command(argv[i + 1]);
        char help_flag[] = "--help";
        char* args[] = {argv[i + 1], help_flag, nullptr};
        return c->run(2, args);
    }
    const Command* c = find_command(name);
    if (!c) throw unknown_command(name);
    return c->run(argc - i, argv + i);
}

}  // namespace

int main(int argc, char** argv) {
    // Subcommands may let exceptions escape: usage errors exit 2, anything
    // else (e.g. kappa::MeshLoadError, "PATH: problem") prints one line, exit 1.
    try {
        return dispatch(argc, argv);
    } catch (const UsageError& e) {
        std::cerr << e.what() << "\n";
        return 2;
    } catch (const std::bad_alloc&) {
        return kappa::cli::fail("out of memory");
    } catch (const std::exception& e) {
        return kappa::cli::fail(e.what());
    }
}
