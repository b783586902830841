// The view-independent line types of the CPU line pass (render/cpu_lines.h):
// ridges, valleys, parabolic and H = 0 lines (geometry/lines/curvature_lines.h)
// and topographic lines (level_lines.h) depend only on the mesh, its fields
// and their own settings, not on the view. They are extracted and chained
// once per block of faces, the first time a view needs the block, and kept
// until the fields or those settings change: when orbiting, a frame only
// merges them on screen (render/screen_merge.h).
//
// A block's lines come from all of its faces, whatever the cluster culling
// of the frame keeps: culled clusters hold no visible lines
// (render/cluster_culling.h), so this draws what drawing every triangle draws.
#pragma once

#include "geometry/lines/chain.h"
#include "geometry/lines/level_lines.h"
#include "geometry/lines/line_extraction.h"
#include "geometry/surface_fields.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace kappa::render {

class MeshBuffers;

// Faces [block * kLineBlockFaces, (block + 1) * kLineBlockFaces) form a block
// of the CPU line pass: segments are chained within a block.
constexpr uint32_t kLineBlockFaces = 2048;

// Whether a line type is one of those kept here.
bool is_view_independent(LineType type);

class ViewIndependentLines {
public:
    // The polylines of each line type (empty for the types not kept) of one block.
    using BlockLines = std::array<std::vector<Polyline>, kLineTypeCount>;

    // Forgets the kept lines when the mesh's fields or the settings in
    // `options` that these types read (which are on, rv_threshold, fade,
    // feature_size, topo_levels) changed since the last call.
    void use(const MeshBuffers& mesh, const LineExtractionOptions& options);
    // Whether any view-independent type is on.
    bool any() const { return any_; }
    // The lines of block b, made on first use. Safe to call from several
    // threads at once for different blocks.
    const BlockLines& block(uint32_t b, const Mesh& mesh, const SurfaceFields& fields);

private:
    uint64_t fields_version_ = 0;
    LineExtractionOptions options_;
    bool any_ = false;
    std::vector<float> heights_;  // topographic lines' values (y)
    std::vector<std::unique_ptr<BlockLines>> blocks_;
};

}  // namespace kappa::render
