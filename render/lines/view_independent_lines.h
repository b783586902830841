// The view-independent line types of the CPU line pass (render/lines/cpu_lines.h):
// ridges, valleys, parabolic and H = 0 lines (geometry/lines/curvature_lines.h)
// and topographic lines (level_lines.h) depend only on the mesh, its fields
// and their own settings, not on the view. Their segments are extracted once
// per block of faces, the first time a view needs the block, and kept, face
// by face, until the fields or those settings change: when orbiting, a frame
// gathers the segments of the faces its culling keeps instead of testing
// those faces again (chaining and merging on screen stay per frame, over the
// same segments as extraction would give, so the image is the same).
#pragma once

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

class ViewIndependentLines {
public:
    // Forgets the kept lines when the mesh's fields or the settings in
    // `options` that these types read (which are on, rv_threshold, fade,
    // feature_size, topo_levels) changed since the last call.
    void use(const MeshBuffers& mesh, const LineExtractionOptions& options);
    // Appends the segments of faces [first, first + count), all in one block,
    // to `lines` (by type, in face order), extracting the block's on first use;
    // with cull_back_faces, not those of faces turned away from `eye`
    // (faces_eye). Safe to call from several threads at once for different blocks.
    void append_faces(uint32_t first, uint32_t count, const Mesh& mesh, const SurfaceFields& fields,
                      bool cull_back_faces, glm::vec3 eye, ExtractedLines& lines);

private:
    struct Block {
        std::vector<uint32_t> face_start;  // kLineBlockFaces + 1 offsets into segments
        std::vector<LineSegment> segments;
        std::vector<uint8_t> types;        // LineType of each segment
    };
    const Block& block(uint32_t b, const Mesh& mesh, const SurfaceFields& fields);

    uint64_t fields_version_ = 0;
    LineExtractionOptions options_;
    LevelValues levels_;  // topographic lines' values (heights)
    std::vector<std::unique_ptr<Block>> blocks_;
};

}  // namespace kappa::render
