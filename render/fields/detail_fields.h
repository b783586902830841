// The curvature fields a drawing uses at a detail setting (RenderSettings::
// detail, `--detail PX`): per vertex, the scale space (geometry/scale/
// scale_space.h) at sigma = max(detail x the pixel size at the vertex,
// noise floor). Features much smaller than `detail` pixels on screen draw
// no lines; zooming in (smaller pixels on the surface) brings finer ones.
// Finer than the scale space's first level, the raw 1-ring estimate is
// blended in only where the mesh's raw C is scale-consistent
// (geometry/scale/raw_consistency.h); on irregular tessellations it is not,
// and no fields are finer than 2 mean edges.
// The noise floor keeps scan noise out of drawings seen from far or close:
// the normal-smoothing width `--smooth auto` would choose for the mesh's
// noise (geometry/scale/auto_smoothing.h), zero on clean meshes.
//
// Occluding contours and shading take the surface at one pixel: the outline
// stays on the visible silhouette of the polygons whatever the detail. On
// noisy meshes it is smoothed just enough that noise draws no contours, and
// the drawn positions are those of that smoothed surface too (the same
// scale as the contour normals, geometry/scale/scale_space.h's
// surface_at_scale): the contour is the smoothed surface's, and noise bumps
// neither shift it nor hide it. Where the contour normals are the raw ones
// (clean meshes, a pixel finer than the first level) the mesh is drawn as it is.
#pragma once

#include "geometry/mesh/mesh.h"
#include "geometry/mesh/vertex_faces.h"
#include "geometry/scale/scale_space.h"
#include "geometry/surface_fields.h"
#include "render/camera/camera.h"

#include <vector>

namespace kappa::render {

// What the detail pipeline keeps per mesh: the scale space and noise floor.
// A noisy mesh (a noise floor above zero) is drawn denoised: its surface at
// the noise floor (scale_space.h's surface_at_scale, positions and all), and
// that surface's own raw fields, scale space and noise floors stand in for
// the mesh's. The noise is below the scale of any drawing, so the lines are
// those of the smoothed surface, and they are drawn where it is: the
// occluding contour hugs the drawn silhouette, and the fields' fits see
// little of the noise (measured on irregular 82k-face shapes with noise of
// 0.1 and 0.33 edges: bench/bench_render_detail).
struct DetailSource {
    ScaleSpace space;
    float noise_floor = 0;    // model units: no fields below this scale
    float contour_floor = 0;  // model units: no contour normals below this scale
    float denoised_at = 0;    // model units: the scale of the denoising (0: the mesh is drawn as given)
    Mesh denoised;                // empty unless denoised_at > 0
    SurfaceFields denoised_raw;   // its raw fields (normals first; curvature when a view needs it)
    // Whether the raw C may be blended in below the first level: unknown
    // until a view first needs it (the test needs the raw curvature).
    enum class Raw { Unknown, Consistent, Inconsistent } raw = Raw::Unknown;
};

// raw: compute_surface_fields(mesh) without smoothing.
// adjacency: the mesh's vertex-face rows when the caller has them (null: built here).
DetailSource make_detail_source(const Mesh& mesh, const SurfaceFields& raw, const VertexFaces* adjacency = nullptr);

struct DetailFields {
    Mesh mesh;                            // as drawn: the positions of the surface at pixel scale
    SurfaceFields fields;                 // at the detail scale
    std::vector<glm::vec3> fine_normals;  // at pixel scale: contours and shading
    float feature_size = 1;               // fs of `fields` (geometry/curvature/feature_size.h)
};

// Fields for one view: camera, image height in pixels, detail in pixels
// (> 0). raw: compute_surface_fields(mesh).
DetailFields detail_fields(const Mesh& mesh, DetailSource& source, const SurfaceFields& raw, const Camera& camera,
                           int image_height, float detail_px);

// The same in two steps, for callers that start from compute_surface_normals
// (cheaper) and compute the raw curvature only when a view needs it.
struct ViewScales {
    std::vector<float> sigma;  // per vertex: the fields' scale
    std::vector<float> fine;   // per vertex: the contour and shading normals' scale
};
ViewScales view_scales(const Mesh& mesh, const DetailSource& source, const Camera& camera, int image_height,
                       float detail_px);
// Whether some vertex blends in the raw estimate (or the raw C's consistency
// is still to be tested), so raw must have curvature. False for a denoised
// source: it completes its own raw fields.
bool needs_raw_curvature(const DetailSource& source, const ViewScales& scales);
// Whether these scales blend in the raw estimate, or must first test its
// consistency, whatever the source (a denoised one's own raw fields then).
bool scales_need_raw_curvature(const DetailSource& source, const ViewScales& scales);
// Throws std::invalid_argument when raw lacks curvature that the scales need.
// (render/fields/detail_fields_job.h: the same work in steps.)
DetailFields detail_fields(const Mesh& mesh, DetailSource& source, const SurfaceFields& raw,
                           const ViewScales& scales);

}  // namespace kappa::render
