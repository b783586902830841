// kappa.batch and kappa.read_manifest: `kappa batch` (app/batch.h) on the
// module's GL context.
#include "bindings.h"
#include "gl_session.h"

#include "app/batch.h"

#include <optional>

namespace kappa::python {

namespace {

// A path, or a list of manifest lines (relative paths: to base_dir, or as given).
std::vector<app::BatchJob> manifest_jobs(const py::handle& manifest, const py::object& base_dir) {
    if (py::isinstance<py::list>(manifest) || py::isinstance<py::tuple>(manifest)) {
        std::string text;
        for (const py::handle line : manifest) text += line.cast<std::string>() + "\n";
        return app::parse_manifest(text, "<lines>", base_dir.is_none() ? "" : path_text(base_dir));
    }
    return app::read_manifest(path_text(manifest));
}

py::dict job_dict(const app::BatchJob& job) {
    py::dict out;
    out["line"] = job.line;
    out["mesh"] = job.mesh;
    out["output"] = job.output;
    py::list options;
    for (const auto& o : job.options) options.append(o);
    out["options"] = options;
    return out;
}

}  // namespace

void def_batch(py::module_& m) {
    m.def(
        "batch",
        [](const py::handle& manifest, const py::object& shard, bool skip_existing, bool progress,
           const py::object& base_dir) {
            int index = 0, count = 1;
            if (!shard.is_none()) {
                const auto t = shard.cast<std::pair<int, int>>();
                index = t.first, count = t.second;
                if (count < 1 || index < 0 || index >= count)
                    throw py::value_error("shard expects (i, n) with 0 <= i < n, got (" + std::to_string(index) +
                                          ", " + std::to_string(count) + ")");
            }
            std::vector<app::BatchJob> jobs;
            try {
                jobs = app::shard_jobs(manifest_jobs(manifest, base_dir), index, count);
            } catch (const std::runtime_error& e) {
                throw py::value_error(e.what());
            }
            app::BatchOptions options;
            options.skip_existing = skip_existing;
            options.progress = progress;
            app::BatchReport report;
            {
                py::gil_scoped_release unlocked;
                std::optional<CurrentRenderer> current;  // made on the first render job, held to the end
                report = app::run_batch(jobs, options, [&]() -> render::Renderer& {
                    if (!current) current.emplace();
                    return current->renderer();
                });
            }
            py::list failures;
            for (const auto& f : report.failures) {
                py::dict d;
                d["line"] = f.line, d["output"] = f.output, d["reason"] = f.reason;
                failures.append(d);
            }
            py::dict out;
            out["jobs"] = report.jobs, out["written"] = report.written, out["skipped"] = report.skipped;
            out["failed"] = failures;
            out["seconds"] = report.seconds;
            out["summary"] = app::batch_summary(report);
            return out;
        },
        py::arg("manifest"), py::kw_only(), py::arg("shard") = py::none(), py::arg("skip_existing") = true,
        py::arg("progress") = false, py::arg("base_dir") = py::none(),
        R"(Runs a batch manifest as `kappa batch` does (docs/batch.md), never stopping at a failure.

manifest: a path (relative paths inside are relative to its folder) or a list of lines
  'MESH OUTPUT [OPTIONS...]' (relative to base_dir, else the current directory).
shard: (i, n): only the meshes numbered i, i + n, ... in order of first appearance.
skip_existing: skip jobs whose output exists (False: as --force). progress: a line per job with
  an ETA on stderr.
Returns {'jobs', 'written', 'skipped', 'failed': [{'line', 'output', 'reason'}], 'seconds',
'summary'}. Render jobs share the module's GL context (kappa.gl_context()). Raises ValueError for an
unreadable or malformed manifest.)");
    m.def(
        "read_manifest",
        [](const py::handle& manifest, const py::object& base_dir) {
            std::vector<app::BatchJob> jobs;
            try {
                jobs = manifest_jobs(manifest, base_dir);
            } catch (const std::runtime_error& e) {
                throw py::value_error(e.what());
            }
            py::list out;
            for (const auto& job : jobs) out.append(job_dict(job));
            return out;
        },
        py::arg("manifest"), py::kw_only(), py::arg("base_dir") = py::none(),
        R"(The jobs of a manifest, as kappa.batch reads them: a list of {'line', 'mesh' ('' for the built-in
model), 'output', 'options'} with relative paths resolved. Group by 'mesh' to plan work: shard
(g, n) of kappa.batch runs the meshes g, g + n, ... in order of first appearance.)");
}

}  // namespace kappa::python
