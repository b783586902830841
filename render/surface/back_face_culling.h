// Per frame: may the surface pass cull back faces, and where must it draw
// them all the same (geometry/culling/back_faces.h)? Culled, llvmpipe sets up half
// the triangles: the surface pass of bunny-1M costs a third less.
#pragma once

#include "geometry/culling/back_faces.h"
#include "render/camera/camera.h"
#include "render/lines/cluster_culling.h"
#include "render/camera/frame_params.h"

#include <glm/vec4.hpp>

#include <vector>

namespace kappa::render {

struct BackFaceCulling {
    bool cull = false;      // draw front faces only, then the back faces of back_runs within `holes`
    bool mirrored = false;  // the view turns the winding round: front faces are clockwise on screen
    std::vector<glm::ivec4> hole_rects;  // (x, y, width, height) in pixels, bottom-left origin, as glScissor
    glm::ivec4 holes{0};                 // their union
    std::vector<FaceRun> back_runs;      // the clusters that may put a back face inside a hole's rectangle
};

// Culls when the mesh is cullable, the eye lies outside its bounding sphere,
// and the holes' union covers at most half the image (else drawing back
// faces in it would cost more than culling saves). back_runs:
// back_facing_runs_in (render/lines/cluster_culling.h) of the holes' rectangles.
BackFaceCulling back_face_culling(const BackFaceVisibility& visibility, const BoundingSphere& bounds,
                                  const MeshClusters& clusters, const FrameParams& frame);

}  // namespace kappa::render
