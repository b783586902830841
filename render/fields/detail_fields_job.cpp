#include "render/fields/detail_fields_job.h"

#include "geometry/curvature/feature_size.h"
#include "geometry/scale/raw_consistency.h"
#include "geometry/surface_analysis.h"

#include <algorithm>
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
        steps_.add_once([this] { source_.denoised_raw = compute_surface_fields(source_.denoised); });
    steps_.add_once([this] { plan_consistency(); });
}

const Mesh& DetailFieldsJob::mesh() const { return source_.denoised_at > 0 ? source_.denoised : input_; }

const SurfaceFields& DetailFieldsJob::raw() const {
    return source_.denoised_at > 0 ? source_.denoised_raw : input_raw_;
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
    auto judged = [this, floor_sigma](RawConsistency verdict) {
        source_.raw = verdict.consistent ? DetailSource::Raw::Consistent : DetailSource::Raw::Inconsistent;
        floor_sigma();
        plan_fields();
    };
    if (!consistency_testable(space, raw())) {
        steps_.add_once([judged] { judged({}); });
        return;
    }
    // The fields at levels 0 and 1 at the sampled vertices, blended in pieces.
    fit(levels_to_fit(space, {space.level_scale(0), space.level_scale(1)}));
    for (size_t level : {0, 1}) {
        SurfaceFields* at = level == 0 ? &first_ : &second_;
        steps_.add_once([this, at, level] {
            sampled_ = consistency_scales(mesh(), source_.space, level);
            *at = fields_to_blend(mesh(), raw());
        });
        steps_.add_chunks(mesh().vertex_count(), chunk_, [this, at](size_t first, size_t last) {
            blend_fields(mesh(), source_.space, raw(), sampled_, first, last, *at);
        });
    }
    steps_.add_once([this, judged] {
        judged(judge_consistency(mesh(), raw(), first_, second_));
        first_ = second_ = {};
    });
}

void DetailFieldsJob::plan_fields() {
    std::vector<size_t> levels = levels_to_fit(source_.space, scales_.fine);
    for (size_t l : levels_to_fit(source_.space, sigma_))
        if (std::find(levels.begin(), levels.end(), l) == levels.end()) levels.push_back(l);
    std::sort(levels.begin(), levels.end());
    fit(levels);
    steps_.add_once([this] { plan_blends(); });
}

void DetailFieldsJob::plan_blends() {
    // Occluding contours and shading: the surface at the fine scales.
    const size_t n = mesh().vertex_count();
    fine_ = {mesh().positions, raw().normals};
    steps_.add_chunks(n, chunk_, [this](size_t first, size_t last) {
        blend_surface(mesh(), source_.space, raw(), scales_.fine, first, last, fine_);
    });
    // The other lines: the fields at the detail scales.
    steps_.add_once([this] {
        out_.fine_normals = std::move(fine_.normals);
        out_.mesh.positions = std::move(fine_.positions);
        out_.mesh.faces = mesh().faces;
        out_.fields = fields_to_blend(mesh(), raw());
    });
    steps_.add_chunks(n, chunk_, [this](size_t first, size_t last) {
        blend_fields(mesh(), source_.space, raw(), sigma_, first, last, out_.fields);
    });
    steps_.add_once([this] { out_.feature_size = feature_size(mesh(), out_.fields); });
}

void DetailFieldsJob::fit(const std::vector<size_t>& levels) {
    if (levels.empty()) return;
    if (chunk_ == 0) {  // side by side on the threads
        steps_.add_once([this, levels] { fit_levels(mesh(), source_.space, raw(), levels); });
        return;
    }
    for (size_t level : levels) {
        auto fitting = std::make_shared<std::unique_ptr<LevelFitSteps>>();
        steps_.add([this, level, fitting] {
            if (!*fitting) *fitting = std::make_unique<LevelFitSteps>(mesh(), source_.space, raw(), level, chunk_);
            (*fitting)->step();
            return (*fitting)->done();
        });
    }
}

}  // namespace kappa::render
