// The line-drawing renderer: a mesh uploaded once, drawn per view with the
// settings of render_settings.h into any framebuffer (an offscreen FBO for
// `kappa render`, a window's default framebuffer for the viewer).
//
// Per frame: surface pass (optionally 4x MSAA) -> resolve into colour and
// depth textures -> line passes into a coverage texture (depth-tested
// against the surface depth), hatching strokes with them -> composite into
// the target -> colour bar.
#pragma once

#include "render/camera/camera.h"
#include "render/surface/depth_raster.h"
#include "render/gl/framebuffer.h"
#include "render/hatching/background_hatching.h"
#include "render/hatching/hatch_field.h"
#include "render/hatching/shader_hatching.h"
#include "render/lines/line_renderer.h"
#include "render/fields/mesh_buffers.h"
#include "render/render_settings.h"
#include "render/compose/screen_passes.h"
#include "render/hatching/stroke_pass.h"
#include "render/vector/strokes.h"
#include "render/surface/surface_renderer.h"

#include <memory>

namespace kappa::render {

class Renderer {
public:
    Renderer();  // compiles every shader; needs a current GL 3.3 core context (4.3 for the compute line path)
    ~Renderer();

    // Uploads the mesh and its fields (replacing any previous mesh).
    // fine_normals: see MeshBuffers::update_fields.
    void set_mesh(const Mesh& mesh, const SurfaceFields& fields, float feature_size,
                  const std::vector<glm::vec3>& fine_normals = {});
    // The same from what MeshBuffers::prepare made beforehand (any thread): GL calls alone.
    void set_mesh(const Mesh& mesh, MeshBuffers::Prepared&& prepared);
    // ... or buffers already made and filled (a first view sent in slices: MeshBuffers::InSlices).
    void set_mesh(std::unique_ptr<MeshBuffers> buffers);
    // New fields for the mesh already uploaded (same vertices and faces).
    void update_fields(const Mesh& mesh, const SurfaceFields& fields, float feature_size,
                       const std::vector<glm::vec3>& fine_normals = {});
    // Sharp edges of the uploaded mesh (crease_end_points, field_upload.h).
    void set_creases(const std::vector<glm::vec3>& end_points);
    // Fields prepared on another thread (render/fields/field_upload.h).
    void upload_fields(FieldUpload&& prepared);
    // The same in slices, drawing the fields uploaded before until the last
    // one (MeshBuffers::begin_upload): for a viewer's frames.
    void begin_field_upload(FieldUpload&& prepared);
    bool continue_field_upload(size_t bytes);  // true when nothing is pending any more
    bool field_upload_pending() const { return mesh_ && mesh_->upload_pending(); }
    const MeshBuffers* mesh() const { return mesh_.get(); }

    // The surface depth of the last frame drawn (window depth, 1 = background,
    // bottom row first): what the line passes test visibility against.
    std::vector<float> surface_depth() const;

    // Draws one view offscreen, the lines blended over the surface in its own
    // framebuffer (offscreen_framebuffer(), to copy from); render_image also
    // reads it back. Without a mesh, clears to the background.
    void render_offscreen(const Camera& camera, const RenderSettings& settings, int width, int height);
    GLuint offscreen_framebuffer() const { return surface_fb_.id(); }  // what render_offscreen drew into
    Image render_image(const Camera& camera, const RenderSettings& settings, int width, int height);

    // The hatching strokes of a view of width x height (settings.hatching;
    // none without a mesh): streamlines over the hatching field
    // (render/hatching/hatch_field.h, render/hatching/hatch_streamlines.h), in image pixels.
    // Leaves GL_FRAMEBUFFER unbound.
    std::vector<Stroke> hatch_strokes(const Camera& camera, const RenderSettings& settings, int width, int height);

    // Where the lines made on the CPU are drawn: on the CPU
    // (render/lines/line_raster.h; the default on software GL) or as GL quads (the
    // default on GPUs). For tests and benchmarks, to compare the two.
    void set_cpu_line_raster(bool on_cpu) { cpu_line_raster_ = on_cpu; }
    bool cpu_line_raster() const { return cpu_line_raster_; }
    // llvmpipe and the like: GL buffers live in host memory.
    bool software_gl() const { return software_gl_; }
    // Whether the surface and hatching-field passes may cull back faces where none can be seen
    // (render/surface/back_face_culling.h; on by default). For tests and benchmarks.
    void set_back_face_culling(bool on) {
        surface_pass_.set_back_face_culling(on);
        hatch_field_.set_back_face_culling(on);
        back_face_culling_ = on;
    }
    // Whether the depth of a surface the colour of the paper is drawn on the
    // CPU when the lines are (render/surface/depth_raster.h; software GL by
    // default). For tests and benchmarks, to compare with the GL's.
    void set_cpu_surface_depth(bool on) { cpu_surface_depth_ = on; }
    // A viewer's streamline hatching (render/hatching/background_hatching.h):
    // traced on a worker thread once the view rests (set_view_moving(false)),
    // the shader's strokes until they are ready and while the view moves.
    // Off (the default): every frame traces its own, as `kappa render`.
    void set_interactive_hatching(bool on) { interactive_hatching_ = on; }
    void set_view_moving(bool moving) { view_moving_ = moving; }
    // Called on a worker thread when a view's streamlines are ready to be drawn.
    void set_hatching_done(std::function<void()> done) { background_hatching_.set_on_done(std::move(done)); }
    // Streamlines are being traced: a frame should come soon to show them.
    bool hatching_pending() const { return background_hatching_.pending(); }
    // The last frame was hatched with traced streamlines (not the shader's strokes).
    bool drew_streamlines() const { return drew_streamlines_; }
    // Whether --hatch-style shader is drawn by the surface pass per fragment
    // (software GL's default) or once a pixel from targets the surface pass
    // fills (render/hatching/shader_hatching.h; GPUs). For tests and benchmarks.
    void set_hatching_in_surface(bool in_surface) { hatching_in_surface_ = in_surface; }
    // Where this context extracts the lines of `settings` (never Auto; render_settings.h).
    LineExtraction line_path(const RenderSettings& settings) const;
    // With the compute path, whether every frame waits until its segment
    // buffer held all its lines (true, the default: images for files) or is
    // drawn at once while the buffer grows for the next frame (a viewer).
    void set_complete_frames(bool complete) { line_pass_.set_complete_frames(complete); }
    // The compute path's segment buffer (render/lines/segment_buffer.h; null
    // without GL 4.3). For tests and benchmarks.
    SegmentBuffer* segment_buffer() { return line_pass_.segment_buffer(); }
    // GPU times of the last frame's line passes (LineRenderer::gpu_times), for benchmarks.
    void set_line_gpu_timing(bool on) { line_pass_.set_gpu_timing(on); }
    LineRenderer::GpuTimes line_gpu_times() const { return line_pass_.gpu_times(); }

private:
    void ensure_buffers(int width, int height, bool msaa);
    // Steps 1 and 2 of a frame: the surface into surface_fb_, the lines' coverage into lines_fb_ (where: ink_).
    FrameParams draw_surface_and_lines(const Camera& camera, const RenderSettings& settings, int width, int height);
    std::vector<Stroke> hatch_strokes(const FrameParams& frame, const RenderSettings& settings);
    std::vector<glm::vec2> hatch_seeds_in_view(const FrameParams& frame, const HatchField& field) const;

    std::unique_ptr<MeshBuffers> mesh_;
    SurfaceRenderer surface_pass_;
    LineRenderer line_pass_;
    HatchFieldPass hatch_field_;
    ShaderHatchingPass shader_hatching_;
    BackgroundHatching background_hatching_;
    bool interactive_hatching_ = false, view_moving_ = false, drew_streamlines_ = false;
    StrokePass stroke_pass_;
    Compositor compositor_;
    ColorBar colorbar_;
    Framebuffer surface_ms_fb_;  // multisampled surface (when MSAA is on)
    Framebuffer surface_fb_;     // colour + depth textures
    Framebuffer lines_fb_;
    InkArea ink_;  // where this frame's lines are in lines_fb_
    bool software_gl_ = false;  // llvmpipe and the like: RenderSettings::line_extraction auto means CPU
    bool cpu_line_raster_ = false;  // software_gl_ unless set_cpu_line_raster
    bool cpu_surface_depth_ = false;  // software_gl_ unless set_cpu_surface_depth
    bool hatching_in_surface_ = false;  // software_gl_ unless set_hatching_in_surface
    bool back_face_culling_ = true;
    mutable DepthRaster depth_raster_;  // surface_depth() draws with it on OpenGL ES
    FrameParams last_frame_;
    const std::vector<float>* cpu_depth_ = nullptr;  // the last frame's surface depth when drawn on the CPU (in depth_raster_)
};

// Headless convenience: renders into an offscreen RGBA8 framebuffer of
// width x height and reads it back (straight alpha, top row first).
Image render_to_image(Renderer& renderer, const Camera& camera, const RenderSettings& settings, int width,
                      int height);

}  // namespace kappa::render
