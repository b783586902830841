// Small helpers shared by the test executables.
#pragma once

#include <string>

namespace kappa::test {

// Path of a mesh in ../shared/meshes (set at configure time).
std::string shared_mesh(const std::string& name);

// A fresh empty directory under the system temp dir, unique per call.
std::string temp_dir();

struct CommandResult {
    int exit_code = -1;
    std::string output;  // stdout and stderr together
};

// Number of '\n' in text: how many lines a command printed.
size_t count_lines(const std::string& text);

// Runs a shell command, capturing its output.
CommandResult run_command(const std::string& command);

// Runs a command (`kappa view ...`) under Xvfb (xvfb-run -a, a 1280x800x24 screen,
// Xvfb -noreset) and retries, at most twice, when Xvfb itself failed.
//
// -noreset: Xvfb resets when its last client leaves and then signals its
// parent (SIGUSR1, as at start-up); xvfb-run (dash) traps that signal, and a
// trapped signal landing while its exit trap runs `rm -r` makes that rm look
// failed: "problem while cleaning up temporary directory", exit status 5
// instead of kappa's (seen once in ~300 runs on CI).
CommandResult run_under_xvfb(const std::string& command);

// Writes text (or bytes) to a file, creating or truncating it.
void write_file(const std::string& path, const std::string& contents);
std::string read_file(const std::string& path);
// Standard base64 (RFC 4648, with padding), for data: URIs in test glTF files.
std::string base64(const std::string& bytes);

}  // namespace kappa::test
