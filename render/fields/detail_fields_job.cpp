#include "render/fields/detail_fields_job.h"

#include "geometry/curvature/feature_size.h"
#include "geometry/scale/raw_consistency.h"
#include "geometry/surface_analysis.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

namespace kappa::render {

namespace {

// Where the raw C is not scale-consistent (an irregular tessellation), no
// fields finer than 2 mean edges: on the accuracy lab's torus with vertices
// jittered by 0.3 cells the errors of k and C are 1.5% and 9.6% there,
// near their least (1.7% and 14% at the first level, 1.5 edges; 1.9% and
// 8.7% at 3 edges; 4.6% and 118% raw).
constexpr float kIrregularFloorEdges = 2.0f;

}  // namespace

DetailFieldsJob::DetailFieldsJob(const Mesh& mesh, DetailSource& source, const SurfaceFields& raw, ViewScales scales,
                                 size_t chunk)
    : input_(mesh), source_(source), input_raw_(raw), scales_(std::move(scales)), chunk_(chunk),
      sigma_(scales_.sigma) {
    // A denoised source completes its own raw fields when the scales need its curvature.
    if (source_.denoised_at > 0 && !source_.denoised_raw.has_curvature() &&
        scales_need_raw_curvature(source_, scales_))
        steps_.push_back([this] {
            source_.denoised_raw = compute_surface_fields(source_.denoised);
            return true;
        });
    steps_.push_back([this] {
        plan_consistency();
        return true;
    });
}

const Mesh& DetailFieldsJob::mesh() const { return source_.denoised_at > 0 ? source_.denoised : input_; }

const SurfaceFields& DetailFieldsJob::raw() const {
    return source_.denoised_at > 0 ? source_.denoised_raw : input_raw_;
}

void DetailFieldsJob::step() {
    if (done()) return;
    if (steps_.front()()) steps_.pop_front();
}

bool DetailFieldsJob::run_for(double seconds) {
    const auto start = std::chrono::steady_clock::now();
    do step();
    while (!done() && std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < seconds);
    return done();
}

DetailFields DetailFieldsJob::take() { return std::move(out_); }

// Finer than the first level, the raw C is blended in only where it is
// scale-consistent (geometry/scale/raw_consistency.h), tested once per source
// on levels 0 and 1.
void DetailFieldsJob::plan_consistency() {
    if (!raw().has_curvature() && scales_need_raw_curvature(source_, scales_))
        throw std::invalid_argument("detail_fields: these scales need the raw curvature");
    ScaleSpace& space = source_.space;
    if (space.empty() || !uses_raw_estimate(space, sigma_)) return plan_fields();
    auto floor_sigma = [this] {
        const float mean_edge = 2.0f * source_.space.raw_scale;  // the raw scale is half a mean edge
        if (source_.raw == DetailSource::Raw::Inconsistent)
            for (float& s : sigma_) s = std::max(s, kIrregularFloorEdges * mean_edge);
    };
    if (source_.raw != DetailSource::Raw::Unknown) {
        floor_sigma();
        return plan_fields();
    }
    const float first = space.level_scale(0), second = space.level_scale(std::min<size_t>(1, space.levels.size() - 1));
    fit(levels_to_fit(space, {first, second}));
    steps_.push_back([this, floor_sigma] {
        source_.raw = raw_dcurv_consistency(mesh(), source_.space, raw()).consistent
                          ? DetailSource::Raw::Consistent
                          : DetailSource::Raw::Inconsistent;
        floor_sigma();
        plan_fields();
        return true;
    });
}

void DetailFieldsJob::plan_fields() {
    std::vector<size_t> levels = levels_to_fit(source_.space, scales_.fine);
    for (size_t l : levels_to_fit(source_.space, sigma_))
        if (std::find(levels.begin(), levels.end(), l) == levels.end()) levels.push_back(l);
    std::sort(levels.begin(), levels.end());
    fit(levels);
    steps_.push_back([this] {
        plan_blends();
        return true;
    });
}

void DetailFieldsJob::plan_blends() {
    // Occluding contours and shading: the surface at the fine scales.
    fine_ = {mesh().positions, raw().normals};
    for_each_chunk([this](size_t first, size_t last) {
        blend_surface(mesh(), source_.space, raw(), scales_.fine, first, last, fine_);
    });
    // The other lines: the fields at the detail scales.
    steps_.push_back([this] {
        out_.fine_normals = std::move(fine_.normals);
        out_.mesh.positions = std::move(fine_.positions);
        out_.mesh.faces = mesh().faces;
        out_.fields = fields_to_blend(mesh(), raw());
        return true;
    });
    for_each_chunk([this](size_t first, size_t last) {
        blend_fields(mesh(), source_.space, raw(), sigma_, first, last, out_.fields);
    });
    steps_.push_back([this] {
        out_.feature_size = feature_size(mesh(), out_.fields);
        return true;
    });
}

void DetailFieldsJob::fit(const std::vector<size_t>& levels) {
    if (levels.empty()) return;
    if (chunk_ == 0) {  // side by side on the threads
        steps_.push_back([this, levels] {
            fit_levels(mesh(), source_.space, raw(), levels);
            return true;
        });
        return;
    }
    for (size_t level : levels) {
        auto fitting = std::make_shared<std::unique_ptr<LevelFitSteps>>();
        steps_.push_back([this, level, fitting] {
            if (!*fitting) *fitting = std::make_unique<LevelFitSteps>(mesh(), source_.space, raw(), level, chunk_);
            (*fitting)->step();
            return (*fitting)->done();
        });
    }
}

void DetailFieldsJob::for_each_chunk(const std::function<void(size_t, size_t)>& body) {
    const size_t n = mesh().vertex_count(), chunk = chunk_ == 0 ? std::max<size_t>(n, 1) : chunk_;
    for (size_t first = 0; first < n; first += chunk)
        steps_.push_back([body, first, last = std::min(n, first + chunk)] {
            body(first, last);
            return true;
        });
}

}  // namespace kappa::render
