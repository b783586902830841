// Hatching as evenly spaced streamlines (Jobard and Lefer 1997, "Creating
// evenly-spaced streamlines of arbitrary density") of a principal-direction
// field in the image (Hertzmann and Zorin 2000 hatch along smoothed
// principal directions). No OpenGL: it works on a HatchField read back from
// the GPU (render/hatching/hatch_field.h).
//
//   Field:   the doubled-angle vectors (cos 2a, sin 2a) w, w the direction's
//            reliability (0 at umbilics, on flat areas and unreliable
//            vertices), averaged by a Gaussian over the surface (sigma =
//            2 spacings), so that unreliable directions take their
//            neighbours'; where nothing reliable is near, strokes run at 45
//            degrees (as engravers do on flat ground).
//   Density: strokes `spacing / darkness` pixels apart (the darkest tone
//            gets `spacing`); none where that exceeds 8 spacings. The cross
//            family (second direction) starts at darkness 0.4.
//   Seeds:   first the given seeds (surface points projected, in a fixed
//            order: strokes stay attached to the surface from frame to frame),
//            then, as Jobard and Lefer, points one separation to either side
//            of each new streamline.
//   Tracing: RK2 steps of one pixel, both ways from the seed, until the
//            surface ends (background, back-facing, a jump in depth), a
//            neighbour is closer than 0.6 separations, or the stroke reaches
//            its maximum length. Streamlines shorter than 2 spacings are
//            dropped.
#pragma once

#include "render/hatching/hatch_field.h"
#include "render/vector/strokes.h"

#include <glm/vec2.hpp>

#include <vector>

namespace kappa::render {

struct HatchParams {
    float spacing = 4;        // pixels between strokes in the darkest tone
    float max_length = 120;   // pixels
    int family = 0;           // along d1 (0, max) or d2 (1, min)
    bool cross_family = false;  // the second family of cross hatching: only in the darker tones
    float taper = 6;          // pixels: stroke ends thin out over this length
};

// seeds: window pixels (x right, y up), in priority order. Strokes come back
// in image coordinates (y down), of type LineType::Hatching.
std::vector<Stroke> trace_hatching(const HatchField& field, const std::vector<glm::vec2>& seeds,
                                   const HatchParams& params);

}  // namespace kappa::render
