#include "batch.h"

#include "cli_options.h"
#include "mesh_drawing.h"
#include "mesh_source.h"
#include "render_options.h"

#include "geometry/io/mesh_io.h"
#include "geometry/io/output_file.h"
#include "render/image/image_writer.h"
#include "render/vector/vector_drawing.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <new>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace kappa::app {

namespace fs = std::filesystem;

namespace {

// Words of one manifest line: blanks separate, "..." keeps them, # starts a comment.
std::vector<std::string> split_words(const std::string& line, const std::string& where) {
    std::vector<std::string> words;
    size_t i = 0;
    while (i < line.size()) {
        if (std::isspace(static_cast<unsigned char>(line[i]))) {
            ++i;
            continue;
        }
        if (line[i] == '#') break;
        std::string word;
        bool quoted = false;
        for (; i < line.size() && (quoted || !std::isspace(static_cast<unsigned char>(line[i]))); ++i) {
            const char c = line[i];
            if (c == '"') quoted = !quoted;
            else if (quoted && c == '\\' && i + 1 < line.size() && (line[i + 1] == '"' || line[i + 1] == '\\'))
                word += line[++i];
            else word += c;
        }
        if (quoted) throw std::runtime_error(where + ": unterminated quote");
        words.push_back(word);
    }
    return words;
}

std::string resolved(const std::string& path, const std::string& base_dir) {
    if (base_dir.empty() || path.empty() || fs::path(path).is_absolute()) return path;
    return (fs::path(base_dir) / path).lexically_normal().string();
}

bool is_render_output(const std::string& path) {
    return render::image_format_for(path) || render::vector_format_for(path);
}

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// "kappa batch: problem" -> "problem"
std::string without_prefix(const std::string& message) {
    const std::string prefix = "kappa batch: ";
    return message.rfind(prefix, 0) == 0 ? message.substr(prefix.size()) : message;
}

// Parses a job's options with those declared on p; throws cli::UsageError.
void parse_options(const BatchJob& job, cli::Parser& p) {
    std::vector<std::string> words{"batch"};
    words.insert(words.end(), job.options.begin(), job.options.end());
    std::vector<char*> argv;
    for (auto& w : words) argv.push_back(w.data());
    argv.push_back(nullptr);
    for (const auto& w : job.options)
        if (w == "-h" || w == "--help") throw cli::UsageError("--help is not an option of a job");
    p.parse_or_throw(int(words.size()), argv.data());
}

// The output is written under a temporary name in its folder and renamed
// when complete: an interrupted batch leaves no partial output behind that a
// later run would skip.
std::string partial_path(const std::string& output) {
    const fs::path path(output);
    return (path.parent_path() / (path.stem().string() + ".partial-" + std::to_string(getpid()) +
                                  path.extension().string()))
        .string();
}

template <typename Write>
void write_complete(const std::string& output, Write write) {
    const fs::path parent = fs::path(output).parent_path();
    std::error_code error;
    if (!parent.empty()) fs::create_directories(parent, error);
    if (error) throw std::runtime_error(output + ": cannot create its folder: " + error.message());
    const std::string partial = partial_path(output);
    try {
        write(partial);
    } catch (...) {
        fs::remove(partial, error);
        throw;
    }
    fs::rename(partial, output, error);
    if (error) {
        fs::remove(partial, error);
        throw std::runtime_error(output + ": cannot rename the finished file into place");
    }
}

// One mesh's jobs: the mesh read once, one drawing and one set of curvature
// fields kept while consecutive jobs can share them.
class MeshJobs {
public:
    MeshJobs(const std::string& mesh_path, const RendererSource& renderer)
        : path_(mesh_path), renderer_(renderer) {}

    void run(const BatchJob& job) {
        if (!load_error_.empty()) throw std::runtime_error(load_error_);
        if (!mesh_) {
            try {
                mesh_ = std::make_unique<Mesh>(load_mesh_or_default(path_));
            } catch (const MeshLoadError& e) {
                load_error_ = e.what();  // the same for every job of the mesh
                throw;
            }
        }
        if (is_render_output(job.output)) render(job);
        else curvature(job);
    }

private:
    void render(const BatchJob& job) {
        RenderOptions o;
        cli::Parser p("batch", "", "");
        add_render_options(p, o);
        parse_options(job, p);
        finish_render_options(p, o);
        o.camera.file_up = file_up_axis(path_);  // glTF: +y
        if (render::image_format_for(job.output) == render::ImageFormat::Jpeg && o.settings.background.a < 1.0f)
            throw std::runtime_error("JPEG has no transparency (use .png, or an opaque --background)");
        if (mesh_->face_count() == 0)
            throw std::runtime_error(mesh_display_name(path_) + ": the mesh has no faces: nothing to draw");
        if (!drawing_ || !drawing_->same_preparation(o.settings, o.smoothing)) {
            drawing_.reset();
            drawing_ = std::make_unique<MeshDrawing>(*mesh_, o.settings, o.smoothing);
        }
        const render::Camera camera = make_camera(o.camera, *drawing_, o.size);
        render::Renderer& renderer = renderer_();
        write_complete(job.output, [&](const std::string& path) {
            drawing_->write(renderer, camera, o.settings, o.size, path);
        });
    }

    void curvature(const BatchJob& job) {
        SmoothingOptions smoothing;
        std::string format = io::lower_extension(job.output);
        cli::Parser p("batch", "", "");
        p.smoothing(smoothing).choice("--format", format, {"csv", "ply", "ply-ascii"}, "");
        parse_options(job, p);
        if (!fields_for_ || !same_smoothing(*fields_for_, smoothing)) {
            fields_for_.reset();
            fields_ = compute_surface_fields(*mesh_, smoothing);
            fields_for_ = smoothing;
        }
        write_complete(job.output, [&](const std::string& path) {
            if (format == "csv") write_csv(path, *mesh_, fields_);
            else write_ply(path, *mesh_, fields_, format == "ply");
        });
    }

    std::string path_;
    const RendererSource& renderer_;
    std::unique_ptr<Mesh> mesh_;
    std::unique_ptr<MeshDrawing> drawing_;
    std::string load_error_;
    SurfaceFields fields_;
    std::optional<SmoothingOptions> fields_for_;  // what fields_ was computed with
};

std::string clock_text(double seconds) {
    const long s = long(seconds + 0.5);
    char text[32];
    if (s >= 3600) std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
    else std::snprintf(text, sizeof text, "%ld:%02ld", s / 60, s % 60);
    return text;
}

}  // namespace

std::vector<BatchJob> parse_manifest(const std::string& text, const std::string& name, const std::string& base_dir) {
    std::vector<BatchJob> jobs;
    std::istringstream in(text);
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        const std::string where = name + ":" + std::to_string(number);
        std::vector<std::string> words = split_words(line, where);
        if (words.empty()) continue;
        if (words.size() < 2) throw std::runtime_error(where + ": expected MESH OUTPUT [OPTIONS...], got one word");
        BatchJob job;
        job.line = number;
        job.mesh = words[0] == "-" ? "" : resolved(words[0], base_dir);
        job.output = resolved(words[1], base_dir);
        if (!is_render_output(job.output) && io::lower_extension(job.output) != "csv" &&
            io::lower_extension(job.output) != "ply")
            throw std::runtime_error(where + ": cannot tell the output format of '" + words[1] +
                                     "': use .png, .jpg, .jpeg, .svg, .pdf (render) or .csv, .ply (curvature)");
        for (size_t i = 2; i < words.size(); ++i) {
            std::string w = words[i];
            if (w == "--xf" && i + 1 < words.size()) {
                job.options.push_back(w);
                w = resolved(words[++i], base_dir);
            } else if (w.rfind("--xf=", 0) == 0) {
                w = "--xf=" + resolved(w.substr(5), base_dir);
            }
            job.options.push_back(w);
        }
        jobs.push_back(std::move(job));
    }
    return jobs;
}

std::vector<BatchJob> read_manifest(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(path + ": cannot open the manifest");
    std::ostringstream text;
    text << in.rdbuf();
    return parse_manifest(text.str(), path, fs::path(path).parent_path().string());
}

std::vector<std::vector<BatchJob>> group_by_mesh(const std::vector<BatchJob>& jobs) {
    std::vector<std::vector<BatchJob>> groups;
    std::map<std::string, size_t> index;
    for (const BatchJob& job : jobs) {
        const auto [it, added] = index.emplace(job.mesh, groups.size());
        if (added) groups.emplace_back();
        groups[it->second].push_back(job);
    }
    return groups;
}

std::vector<BatchJob> shard_jobs(const std::vector<BatchJob>& jobs, int index, int count) {
    std::vector<BatchJob> out;
    const auto groups = group_by_mesh(jobs);
    for (size_t g = 0; g < groups.size(); ++g)
        if (int(g % size_t(count)) == index) out.insert(out.end(), groups[g].begin(), groups[g].end());
    return out;
}

BatchReport run_batch(const std::vector<BatchJob>& jobs, const BatchOptions& options, const RendererSource& renderer) {
    const auto start = std::chrono::steady_clock::now();
    BatchReport report;
    report.jobs = jobs.size();
    size_t finished = 0, worked = 0;  // worked: written or failed (skips take no time)
    for (const std::vector<BatchJob>& group : group_by_mesh(jobs)) {
        MeshJobs mesh(group.front().mesh, renderer);
        for (const BatchJob& job : group) {
            ++finished;
            std::error_code error;
            if (options.skip_existing && fs::exists(job.output, error)) {
                ++report.skipped;
                continue;
            }
            ++worked;
            const char* outcome = "written";
            try {
                mesh.run(job);
                ++report.written;
            } catch (const std::bad_alloc&) {
                report.failures.push_back({job.line, job.output, "out of memory"});
                outcome = "FAILED";
            } catch (const std::exception& e) {
                report.failures.push_back({job.line, job.output, without_prefix(e.what())});
                outcome = "FAILED";
            }
            if (!options.progress || !options.log) continue;
            const double elapsed = seconds_since(start);
            const double eta = elapsed / double(worked) * double(jobs.size() - finished);
            std::fprintf(options.log, "kappa batch: [%zu/%zu] %3.0f%%, ETA %s: line %d %s %s\n", finished,
                         jobs.size(), 100.0 * double(finished) / double(jobs.size()), clock_text(eta).c_str(),
                         job.line, job.output.c_str(), outcome);
            std::fflush(options.log);
        }
    }
    std::stable_sort(report.failures.begin(), report.failures.end(),
                     [](const BatchFailure& a, const BatchFailure& b) { return a.line < b.line; });
    report.seconds = seconds_since(start);
    return report;
}

std::string batch_summary(const BatchReport& r) {
    std::string out = std::to_string(r.jobs) + " jobs: " + std::to_string(r.written) + " written, " +
                      std::to_string(r.skipped) + " skipped (output exists), " + std::to_string(r.failures.size()) +
                      " failed\n";
    for (const BatchFailure& f : r.failures)
        out += "  line " + std::to_string(f.line) + ": " + f.output + ": " + f.reason + "\n";
    return out;
}

}  // namespace kappa::app
