// Line passes: every line type of --lines, as screen-space quads (see
// shaders/lines/line_quad.glsl for why), accumulated as anti-aliased coverage
// with GL_MAX blending into the bound one-channel framebuffer. Occlusion is
// tested against the surface depth texture. The per-triangle families are
// cut where --line-extraction says (render_settings.h): in compute passes
// (render/lines/segment_buffer.h), geometry shaders (the same extraction
// functions, shaders/lines/*.glsl), or on the CPU (render/lines/cpu_lines.h).
#pragma once

#include "render/lines/cpu_lines.h"
#include "render/camera/frame_params.h"
#include "render/fields/mesh_buffers.h"
#include "render/render_settings.h"
#include "render/gl/shader_program.h"
#include "render/lines/segment_buffer.h"

#include <future>
#include <memory>

namespace kappa::render {

class LineRenderer {
public:
    LineRenderer();  // compiles the shaders (GL context current); the compute passes too where GL >= 4.3
    ~LineRenderer();
    // Whether --line-extraction compute can run in this context (GL 4.3 or later).
    bool compute_available() const { return compute_ != nullptr; }
    // With the compute path, whether a frame whose segments overflow the
    // segment buffer is drawn again at once (true: images for files) or
    // drawn as it is while the buffer grows for the next frame (a viewer).
    void set_complete_frames(bool complete) { complete_frames_ = complete; }
    // The compute path's segment buffer (null without GL 4.3).
    SegmentBuffer* segment_buffer();
    // For benchmarks: GPU times (GL timestamps) of the last frame's line
    // passes, milliseconds: cutting the lines (compute passes, or the
    // geometry-shader passes, which also draw), and drawing the compute
    // path's segments. Read back at the end of each draw (a stall), only
    // while on.
    struct GpuTimes {
        double extract_ms = 0, draw_ms = 0;
    };
    void set_gpu_timing(bool on) { gpu_timing_ = on; }
    GpuTimes gpu_times() const { return gpu_times_; }
    void clear_gpu_times() { gpu_times_ = {}; }  // a frame without line passes
    // Starts making this frame's lines on the CPU (render/lines/cpu_lines.h) on
    // another thread, so that they are made while the GL draws the surface
    // (a software rasteriser transforms and bins the surface's triangles on
    // the calling thread, leaving the other cores idle). draw() waits for them.
    void begin_cpu_lines(const MeshBuffers& mesh, const FrameParams& frame, const RenderSettings& settings);
    // path: where the lines are extracted, resolved (not Auto): Cpu, the lines of every kind but creases,
    // boundaries and glyphs come from render/lines/cpu_lines.h (begun by begin_cpu_lines, or made here);
    // Gpu, geometry shaders; Compute, compute passes (render/lines/segment_buffer.h), or geometry
    // shaders where the context has none. Into the bound framebuffer, cleared;
    // coverage_texture: 0, or its R8 colour texture, for the CPU to draw
    // those lines into itself (software GL, render/lines/line_raster.h).
    // strokes (render/hatching/stroke_pass.h): drawn with the CPU lines when those are
    // rasterised on the CPU (cpu_lines and coverage_texture), else ignored.
    // cpu_depth: the surface depth when it was drawn on the CPU
    // (render/surface/depth_raster.h; then surface_depth_texture holds none until a
    // GL pass needs it, when it is uploaded). Returns where lines were drawn.
    InkArea draw(const MeshBuffers& mesh, const FrameParams& frame, const RenderSettings& settings, LineExtraction path,
                 GLuint surface_depth_texture, GLuint coverage_texture = 0,
                 const std::vector<WindowSegment>& strokes = {}, const std::vector<float>* cpu_depth = nullptr);

private:
    void set_common(ShaderProgram& p, const MeshBuffers& mesh, const FrameParams& frame,
                    const RenderSettings& settings);
    ShaderProgram isolines_, isolines_highlights_, boundaries_, curvature_lines_, view_ridges_, level_lines_, vectors_,
        creases_;
    struct ComputeFamilies;
    std::unique_ptr<ComputeFamilies> compute_;  // null without GL 4.3
    bool complete_frames_ = true;
    bool gpu_timing_ = false;
    GpuTimes gpu_times_;
    GLuint timestamps_[3] = {0, 0, 0};
    CpuLinePass cpu_lines_;
    std::future<CpuLines> pending_cpu_lines_;
};

}  // namespace kappa::render
