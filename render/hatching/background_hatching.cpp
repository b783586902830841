#include "render/hatching/background_hatching.h"

#include "geometry/parallel/parallel.h"
#include "render/hatching/hatch_streamlines.h"

#include <chrono>
#include <iterator>

namespace kappa::render {

bool HatchViewKey::operator==(const HatchViewKey& o) const {
    return mvp == o.mvp && viewport == o.viewport && light == o.light && hatching == o.hatching &&
           spacing == o.spacing && stroke_width == o.stroke_width && fields_version == o.fields_version;
}

BackgroundHatching::~BackgroundHatching() {
    if (job_.valid()) job_.wait();
}

const std::vector<Stroke>* BackgroundHatching::strokes_for(const HatchViewKey& key) {
    if (job_.valid() && job_.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
        done_ = job_.get();
        done_key_ = job_key_;
        have_done_ = true;
    }
    return have_done_ && done_key_ == key ? &done_ : nullptr;
}

void BackgroundHatching::start(const HatchViewKey& key, HatchField field, std::vector<glm::vec2> seeds,
                               const RenderSettings& settings) {
    if (job_.valid()) return;
    job_key_ = key;
    job_ = std::async(std::launch::async,
                      [field = std::move(field), seeds = std::move(seeds), settings, on_done = on_done_] {
                          std::vector<Stroke> strokes = trace_view_hatching(field, seeds, settings);
                          if (on_done) on_done();
                          return strokes;
                      });
}

std::vector<Stroke> trace_view_hatching(const HatchField& field, const std::vector<glm::vec2>& seeds,
                                        const RenderSettings& s) {
    const size_t families = s.hatching == Hatching::Cross ? 2 : 1;
    std::vector<std::vector<Stroke>> traced(families);
    parallel_for_dynamic(families, [&](size_t family) {
        HatchParams params;
        params.spacing = s.hatch_spacing;
        params.family = s.hatching == Hatching::Min || family == 1 ? 1 : 0;
        params.cross_family = family == 1;
        traced[family] = trace_hatching(field, seeds, params);
    });
    std::vector<Stroke> strokes;
    for (std::vector<Stroke>& family_strokes : traced) {
        for (Stroke& st : family_strokes) st.width = s.hatch_stroke_width;
        strokes.insert(strokes.end(), std::make_move_iterator(family_strokes.begin()),
                       std::make_move_iterator(family_strokes.end()));
    }
    return strokes;
}

}  // namespace kappa::render
