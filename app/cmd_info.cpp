// `kappa info [MESH]`: prints mesh statistics.
#include "cli_options.h"
#include "commands.h"

#include <iostream>
#include <string>

namespace kappa::app {

int run_info(int argc, char** argv) {
    std::string mesh_path;
    cli::Parser p("info", "[MESH] [options]", "Print statistics of a mesh.");
    p.positional("MESH", mesh_path, "mesh file (.ply, .obj); default: the built-in model", false).threads();
    if (auto status = p.parse(argc, argv)) return *status;
    std::cout << "TODO\n";
    return 0;
}

}  // namespace kappa::app
