// `kappa batch MANIFEST [--shard I/N] [options]`: renders and computes for
// many meshes and views (app/batch.h has the manifest's format), skipping
// outputs that exist, reporting failures without stopping.
#include "batch.h"
#include "cli_options.h"
#include "commands.h"
#include "heap_tuning.h"

#include "render/gl/egl_context.h"
#include "render/renderer.h"

#include <cstdio>
#include <fstream>
#include <memory>

namespace kappa::app {

int run_batch(int argc, char** argv) {
    keep_large_blocks();  // views reuse the last view's memory (app/heap_tuning.h)
    std::string manifest, failures_path;
    int shard = 0, shards = 1;
    bool force = false, quiet = false;
    cli::Parser p("batch", "MANIFEST [--shard I/N] [options]",
                  "Render and compute curvature for many meshes and views: one job a line of MANIFEST, "
                  "'MESH OUTPUT [OPTIONS...]', the options those of 'kappa render' (OUTPUT .png .jpg .svg .pdf) "
                  "or 'kappa curvature' (.csv .ply). Each mesh is read once and every view drawn on one GL "
                  "context; outputs that exist are skipped; failures are listed at the end (exit status 1).");
    p.positional("MANIFEST", manifest, "the jobs, one a line (docs/batch.md)", true)
        .option("--shard", "I/N",
                "run only shard I of N (0 <= I < N): the meshes numbered I, I+N, I+2N, ... in order of first "
                "appearance, so that N processes (a Slurm array, say) share the manifest",
                [&](const std::string& v) {
                    const auto parts = cli::split(v, '/');
                    if (parts.size() != 2) return false;
                    const auto i = cli::parse_int(parts[0]), n = cli::parse_int(parts[1]);
                    if (!i || !n || *n < 1 || *i < 0 || *i >= *n) return false;
                    shard = *i, shards = *n;
                    return true;
                },
                "I/N with 0 <= I < N")
        .flag("--force", force, "write every output, even those that exist")
        .text("--failures", failures_path, "also write the failures there, one line each (empty: none failed)",
              "FILE")
        .flag("-q,--quiet", quiet, "no progress lines (the summary of failures is still printed)")
        .threads()
        .epilog("Example manifest (paths relative to its folder; '-' is the built-in model):\n"
                "  bunny.ply  out/bunny-front.png  --view 0,20 --size 512x384\n"
                "  bunny.ply  out/bunny-side.svg   --view 90,20 --shading none\n"
                "  bunny.ply  out/bunny.csv        --smooth auto\n"
                "Slurm: sbatch --array=0-9 --wrap 'kappa batch jobs.txt --shard $SLURM_ARRAY_TASK_ID/10'");
    if (auto status = p.parse(argc, argv)) return *status;

    std::vector<BatchJob> jobs;
    try {
        jobs = shard_jobs(read_manifest(manifest), shard, shards);
    } catch (const std::exception& e) {
        return cli::fail(e.what());
    }
    // One GL context and renderer for every render job, made on the first.
    std::unique_ptr<render::HeadlessContext> context;
    std::unique_ptr<render::Renderer> renderer;
    const RendererSource source = [&]() -> render::Renderer& {
        if (!renderer) {
            if (!context) context = render::HeadlessContext::create();
            renderer = std::make_unique<render::Renderer>();
        }
        return *renderer;
    };
    BatchOptions options;
    options.skip_existing = !force;
    options.progress = !quiet;
    const BatchReport report = run_batch(jobs, options, source);
    const std::string summary = batch_summary(report);
    std::fprintf(stderr, "kappa batch: %s", summary.c_str());
    if (!failures_path.empty()) {
        std::ofstream out(failures_path);
        for (const BatchFailure& f : report.failures)
            out << manifest << ":" << f.line << ": " << f.output << ": " << f.reason << "\n";
        if (!out) return cli::fail(failures_path + ": cannot write the failures");
    }
    return report.failures.empty() ? 0 : 1;
}

}  // namespace kappa::app
