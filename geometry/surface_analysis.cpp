#include "surface_analysis.h"

#include "geometry/curvature/curvature.h"
#include "curvature/estimate.h"
#include "geometry/curvature/dcurvature.h"
#include "geometry/curvature/face_geometry.h"
#include "scale/auto_smoothing.h"
#include "geometry/curvature/smoothing.h"
#include "geometry/mesh/vertex_faces.h"
#include "geometry/curvature/vertex_flags.h"
#include "geometry/curvature/vertex_basics.h"

#include "geometry/parallel/parallel.h"

#include <glm/geometric.hpp>

#include <chrono>

namespace kappa {

namespace {

class StageTimer {
public:
    explicit StageTimer(double* slot) : slot_(slot), start_(std::chrono::steady_clock::now()) {}
    ~StageTimer() {
        if (slot_) *slot_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }

private:
    double* slot_;
    std::chrono::steady_clock::time_point start_;
};

}  // namespace

namespace {

// The last stage of every estimator: optional C smoothing.
template <typename Report>
void smooth_dcurv_stage(const Mesh& mesh, const VertexFaces& vf, const SmoothingOptions& smoothing, StageTimes& t,
                        const Report& report, SurfaceFields& out) {
    if (smoothing.dcurv > 0) {
        report(0.8f, "smoothing derivative");
        StageTimer timer(&t.smoothing);
        smooth_dcurv({mesh, vf, out.point_areas, out.normals}, smoothing.dcurv, out.d1, out.d2, out.dcurv);
    }
    report(1.0f, "done");
}

// The stages from curvature on for every estimator but the default
// (geometry/curvature/estimate.h): the estimator's tensors (and normals),
// optional tensor smoothing, diagonalisation, C (the estimator's, or the
// paper's C step on its tensors), optional C smoothing.
template <typename Report>
void estimate_other(const Mesh& mesh, const VertexFaces& vf, FaceGeometry& faces, const SmoothingOptions& smoothing,
                    StageTimes& t, const Report& report, SurfaceFields& out) {
    report(0.35f, "curvature");
    CurvatureEstimate e;
    {
        StageTimer timer(&t.curvature);
        e = estimate_curvature(smoothing.estimator, {mesh, vf, faces, out.normals, out.point_areas});
        if (!e.normals.empty()) out.normals = std::move(e.normals);
        for (size_t v = 0; v < e.flags.size(); ++v) out.flags[v] |= e.flags[v];
    }
    if (smoothing.curvature > 0) {
        report(0.5f, "smoothing curvature");
        StageTimer timer(&t.smoothing);
        smooth_curvature_tensors({mesh, vf, out.point_areas, out.normals}, smoothing.curvature, e.tensors);
    }
    {
        StageTimer timer(&t.curvature);
        principal_curvatures(e.tensors, out.normals, out.k1, out.k2, out.d1);
    }
    report(0.65f, "derivative of curvature");
    {
        StageTimer timer(&t.dcurv);
        if (e.dcurv_uv.empty()) {
            // The paper's C step (sec. 3.4) on the estimator's tensors; it
            // needs the face frames of the paper's curvature step.
            compute_curvature_tensors(mesh, vf, out.normals, faces.records);
            out.dcurv = compute_dcurv(mesh, vf, std::move(faces.records), out.normals, std::move(e.tensors),
                                      out.d1);
        } else {
            out.dcurv.resize(out.normals.size());
            parallel_for(out.normals.size(), [&](size_t v) {
                glm::vec3 u, w;
                tangent_frame(out.normals[v], u, w);
                // (d1, d2) = (c u - s w, s u + c w), as in compute_dcurv.
                const float c = glm::dot(out.d1[v], u), s = -glm::dot(out.d1[v], w);
                out.dcurv[v] = transform_dcurv(FrameChange{c, -s, s, c}, e.dcurv_uv[v]);
            });
        }
        out.d2 = second_principal_directions(out.normals, out.d1);
    }
    smooth_dcurv_stage(mesh, vf, smoothing, t, report, out);
}

SurfaceFields compute(const Mesh& mesh, const SmoothingOptions& requested, StageTimes* times,
                      const ProgressFn& progress, bool curvature, const VertexFaces* adjacency) {
    StageTimes local;
    StageTimes& t = times ? *times : local;
    auto report = [&](float f, const char* stage) {
        if (progress) progress(f, stage);
    };
    SurfaceFields out;

    report(0.0f, "adjacency");
    VertexFaces built;
    if (!adjacency) {
        StageTimer timer(&t.adjacency);
        built = build_vertex_faces(mesh);
    }
    const VertexFaces& vf = adjacency ? *adjacency : built;

    report(0.1f, "areas");
    FaceGeometry faces;
    {
        StageTimer timer(&t.areas);
        faces = compute_face_geometry(mesh);
    }

    report(0.2f, "normals");
    {
        StageTimer timer(&t.normals);  // with the point areas and the flags, in the same pass
        VertexBasics basics = compute_vertex_basics(vf, faces);
        out.point_areas = std::move(basics.point_areas);
        out.flags = std::move(basics.flags);
        out.normals = std::move(basics.normals);
    }
    out.smoothing = requested;
    if (requested.automatic) {
        report(0.22f, "estimating noise");
        StageTimer timer(&t.smoothing);
        out.noise = estimate_noise_level(mesh, vf, out.normals);
        const SmoothingOptions chosen = choose_smoothing_widths(out.noise);
        if (!(out.smoothing.normals > 0)) out.smoothing.normals = chosen.normals;
        if (!(out.smoothing.curvature > 0)) out.smoothing.curvature = chosen.curvature;
        if (!(out.smoothing.dcurv > 0)) out.smoothing.dcurv = chosen.dcurv;
    }
    const SmoothingOptions& smoothing = out.smoothing;
    if (smoothing.normals > 0) {
        report(0.25f, "smoothing normals");
        StageTimer timer(&t.smoothing);
        smooth_normals({mesh, vf, out.point_areas, out.normals}, smoothing.normals, out.normals);
    }
    // Vertices with no usable face keep a fixed unit normal (they are flagged).
    for (auto& n : out.normals)
        if (n == glm::vec3(0.0f)) n = glm::vec3(0, 0, 1);
    if (!curvature) {
        report(1.0f, "done");
        return out;
    }

    if (smoothing.estimator != Estimator::rusinkiewicz) {
        estimate_other(mesh, vf, faces, smoothing, t, report, out);
        return out;
    }

    report(0.35f, "curvature");
    VertexTensors tensors;
    {
        StageTimer timer(&t.curvature);
        tensors = compute_curvature_tensors(mesh, vf, out.normals, faces.records);  // the records now hold the fits
    }
    if (smoothing.curvature > 0) {
        report(0.5f, "smoothing curvature");
        StageTimer timer(&t.smoothing);
        smooth_curvature_tensors({mesh, vf, out.point_areas, out.normals}, smoothing.curvature, tensors);
    }
    {
        StageTimer timer(&t.curvature);
        principal_curvatures(tensors, out.normals, out.k1, out.k2, out.d1);
    }

    report(0.65f, "derivative of curvature");
    {
        StageTimer timer(&t.dcurv);
        out.dcurv = compute_dcurv(mesh, vf, std::move(faces.records), out.normals, std::move(tensors), out.d1);
        out.d2 = second_principal_directions(out.normals, out.d1);
    }
    smooth_dcurv_stage(mesh, vf, smoothing, t, report, out);
    return out;
}

}  // namespace

SurfaceFields compute_surface_fields(const Mesh& mesh, const SmoothingOptions& smoothing, StageTimes* times,
                                     const ProgressFn& progress, const VertexFaces* adjacency) {
    return compute(mesh, smoothing, times, progress, true, adjacency);
}

SurfaceFields compute_surface_normals(const Mesh& mesh, StageTimes* times, const VertexFaces* adjacency) {
    return compute(mesh, {}, times, {}, false, adjacency);
}

}  // namespace kappa
