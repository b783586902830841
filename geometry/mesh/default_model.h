// The built-in model shown when no mesh is given on the command line: a
// smooth closed blob generated here (no file, no randomness), designed to
// show every kind of line kappa draws from the default +z view: occluding
// contours, suggestive contours (concave dents and a valley seen obliquely),
// saddles (a ring of small alternating bumps) and a ridge for hatching.
#pragma once

#include "mesh.h"

namespace kappa {

// An icosphere subdivided 6 times (40,962 vertices, 81,920 faces), displaced
// radially by a sum of smooth bumps, then stretched slightly, centred at the
// origin (bounding-box centre) and scaled so that its farthest vertex lies at
// distance 1. Closed, manifold, faces counter-clockwise seen from outside.
// Deterministic: fixed parameters, no randomness, identical on every call.
Mesh make_default_model();

// The same shape on another tessellation of the unit sphere (its vertices
// are displaced the same way): e.g. make_icosphere(1, 8) gives 1.3M faces,
// make_jittered_sphere an irregular one. Tests compare drawings of the one
// shape across tessellations.
Mesh make_default_model_from(Mesh unit_sphere);

}  // namespace kappa
