// detail_fields (detail_fields.h) as a resumable job: the same work cut into
// steps of bounded size (one level's clusters, a phase of a level's fit over
// a few thousand clusters, the blend of a few thousand vertices), so that a
// page with one thread (web/) prepares a view's fields in slices between its
// frames instead of freezing. detail_fields() runs the same job in one go:
// the fields are the same bits however the work is cut.
//
// The job keeps references to the mesh, the source and the raw fields: they
// must outlive it. It fills the source's scale space as it goes (a level
// counts as fitted only once complete), so a job dropped half-way (the view
// moved on) leaves the source as good as it found it, and the next one
// starts from the levels already fitted.
#pragma once

#include "render/fields/detail_fields.h"

#include "geometry/parallel/step_queue.h"

namespace kappa::render {

class DetailFieldsJob {
public:
    // chunk: vertices (and clusters) a step; 0: each stage in one step, on all threads.
    DetailFieldsJob(const Mesh& mesh, DetailSource& source, const SurfaceFields& raw, ViewScales scales,
                    size_t chunk = 0);
    DetailFieldsJob(const DetailFieldsJob&) = delete;  // its steps point at it
    DetailFieldsJob& operator=(const DetailFieldsJob&) = delete;
    bool done() const { return steps_.done(); }
    // The next step. Throws std::invalid_argument as detail_fields does.
    void step() { steps_.step(); }
    // Steps until done or until `seconds` have passed (at least one step); returns done().
    bool run_for(double seconds) { return steps_.run_for(seconds); }
    DetailFields take();  // once done

private:
    // Planning steps come last in the queue and add the steps after them.
    void plan_consistency();
    void plan_fields();
    void plan_blends();
    void fit(const std::vector<size_t>& levels);
    const Mesh& mesh() const;          // the input, or the source's denoised surface
    const SurfaceFields& raw() const;  // its raw fields

    const Mesh& input_;
    DetailSource& source_;
    const SurfaceFields& input_raw_;
    ViewScales scales_;
    size_t chunk_;
    std::vector<float> sigma_;  // scales_.sigma, floored where the raw C is not to be trusted
    SurfaceFields first_, second_;  // the consistency test's fields at levels 0 and 1
    std::vector<float> sampled_;     // the scales it samples one of them at
    SurfaceAtScale fine_;
    DetailFields out_;
    StepQueue steps_;
};

}  // namespace kappa::render
