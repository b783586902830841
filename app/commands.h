// Entry points of the kappa subcommands (conventions.md, "Command line
// contract"). Each one receives the arguments after the word `kappa`:
// argv[0] is the subcommand name, argv[1..argc) its own arguments. It returns
// the process exit status: 0 success, 1 runtime failure (unreadable mesh,
// unwritable output), 2 usage error.
//
// Adding a subcommand: define `int run_xxx(int argc, char** argv)` in
// app/cmd_xxx.cpp, declare it here, and add one line to the table in
// app/main.cpp.
#pragma once

namespace kappa::app {

int run_view(int argc, char** argv);       // app/cmd_view.cpp
int run_render(int argc, char** argv);     // app/cmd_render.cpp
int run_curvature(int argc, char** argv);  // app/cmd_curvature.cpp
int run_info(int argc, char** argv);       // app/cmd_info.cpp
int run_batch(int argc, char** argv);      // app/cmd_batch.cpp

}  // namespace kappa::app
