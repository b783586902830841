// `kappa batch`: many meshes, many views and outputs from one manifest
// (docs/batch.md). The manifest has one job a line:
//
//   # comment
//   MESH  OUTPUT  [OPTIONS...]
//
// OUTPUT's extension chooses the job: .png .jpg .jpeg .svg .pdf render the
// mesh with `kappa render`'s options, .csv .ply write `kappa curvature`'s
// fields with its options. Words are separated by blanks; "double quotes"
// keep blanks (\" and \\ inside). MESH `-` is the built-in model. Relative
// paths (MESH, OUTPUT, --xf) are relative to the manifest's folder.
//
// Jobs run grouped by mesh (meshes in the order they first appear): each
// mesh is read once, its curvature computed once per curvature setting, and
// every render job draws through one renderer on one GL context.
#pragma once

#include "geometry/surface_analysis.h"

#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace kappa::render {
class Renderer;
}

namespace kappa::app {

struct BatchJob {
    int line = 0;       // in the manifest, from 1
    std::string mesh;   // "" for the built-in model
    std::string output;
    std::vector<std::string> options;  // as on the command line
};

// Throws std::runtime_error "NAME:LINE: problem" (a job with no OUTPUT, an
// unterminated quote). base_dir: what relative paths are relative to ("": as given).
std::vector<BatchJob> parse_manifest(const std::string& text, const std::string& name, const std::string& base_dir);
// The same from a file (relative to its folder); throws std::runtime_error "PATH: problem".
std::vector<BatchJob> read_manifest(const std::string& path);

// Jobs grouped by mesh, meshes in order of first appearance.
std::vector<std::vector<BatchJob>> group_by_mesh(const std::vector<BatchJob>& jobs);
// The jobs of shard `index` of `count` (0 <= index < count): the mesh groups
// g with g % count == index, so each mesh is read by one shard only.
std::vector<BatchJob> shard_jobs(const std::vector<BatchJob>& jobs, int index, int count);

struct BatchOptions {
    bool skip_existing = true;  // jobs whose output exists are skipped
    bool progress = true;       // one line per job with an ETA on `log`
    std::FILE* log = stderr;
};

struct BatchFailure {
    int line = 0;
    std::string output;
    std::string reason;  // one line
};

struct BatchReport {
    size_t jobs = 0, written = 0, skipped = 0;
    std::vector<BatchFailure> failures;
    double seconds = 0;
};

// A renderer on a GL context current on this thread, made on the first
// render job; it may throw (render::ContextError): those jobs fail.
using RendererSource = std::function<render::Renderer&()>;

// Runs `jobs` (grouped by mesh), never stopping at a failure.
BatchReport run_batch(const std::vector<BatchJob>& jobs, const BatchOptions& options, const RendererSource& renderer);

// "40 jobs: 35 written, 3 skipped (output exists), 2 failed", then one line
// per failure: "  line 7: out/x.png: reason".
std::string batch_summary(const BatchReport& report);

}  // namespace kappa::app
