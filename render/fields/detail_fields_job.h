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

#include <deque>
#include <functional>
#include <memory>

namespace kappa::render {

class DetailFieldsJob {
public:
    // chunk: vertices (and clusters) a step; 0: each stage in one step, on all threads.
    DetailFieldsJob(const Mesh& mesh, DetailSource& source, const SurfaceFields& raw, ViewScales scales,
                    size_t chunk = 0);
    bool done() const { return steps_.empty(); }
    // The next step. Throws std::invalid_argument as detail_fields does.
    void step();
    // Steps until done or until `seconds` have passed (at least one step); returns done().
    bool run_for(double seconds);
    DetailFields take();  // once done

private:
    // A step returns whether it is finished (a level's fit takes several calls).
    // Planning steps come last in the queue and add the steps after them.
    using Step = std::function<bool()>;
    void plan_consistency();
    void plan_fields();
    void plan_blends();
    void fit(const std::vector<size_t>& levels);
    // Steps calling body(first, last) over the vertices, chunk_ at a time.
    void for_each_chunk(const std::function<void(size_t, size_t)>& body);
    const Mesh& mesh() const;          // the input, or the source's denoised surface
    const SurfaceFields& raw() const;  // its raw fields

    const Mesh& input_;
    DetailSource& source_;
    const SurfaceFields& input_raw_;
    ViewScales scales_;
    size_t chunk_;
    std::vector<float> sigma_;  // scales_.sigma, floored where the raw C is not to be trusted
    SurfaceAtScale fine_;
    DetailFields out_;
    std::deque<Step> steps_;
};

}  // namespace kappa::render
