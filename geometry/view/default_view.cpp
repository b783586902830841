#include "default_view.h"

#include "geometry/mesh/position_bounds.h"
#include "geometry/parallel/parallel.h"
#include "geometry/scale/denoise.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>
#include <glm/vec2.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <vector>

namespace kappa {

namespace {

constexpr int kBins = 64;
constexpr size_t kMaxSampledFaces = 200000;
constexpr double kDetailWeight = 1.0;
// A denoised figure's low end carries at least this many times the surface
// of its high end in the end slabs (choose_up, default_view.h).
constexpr double kBlunterEnd = 1.1;

// Fibonacci sphere: kBins nearly uniform directions.
std::array<glm::vec3, kBins> bin_directions() {
    std::array<glm::vec3, kBins> dirs;
    const float golden = float(M_PI) * (3.0f - std::sqrt(5.0f));
    for (int i = 0; i < kBins; ++i) {
        const float y = 1.0f - 2.0f * (float(i) + 0.5f) / float(kBins);
        const float r = std::sqrt(std::max(0.0f, 1.0f - y * y));
        dirs[size_t(i)] = {r * std::cos(golden * float(i)), y, r * std::sin(golden * float(i))};
    }
    return dirs;
}

// Every step-th face (step = ceil(F / kMaxSampledFaces): a deterministic
// sample of big meshes), its corners' numbers and positions gathered once
// for every test below (in parallel: on big meshes they lie all over
// memory), in the coordinates the tests work in (see turned_into).
struct FaceSampling {
    size_t step = 1;
    std::vector<Face> faces;                         // the sampled faces' corners
    std::vector<std::array<glm::vec3, 3>> corners;  // their positions
};

size_t sampling_step(const Mesh& mesh) {
    return std::max<size_t>(1, (mesh.face_count() + kMaxSampledFaces - 1) / kMaxSampledFaces);
}

FaceSampling sample_faces(const Mesh& mesh) {
    FaceSampling s;
    s.step = sampling_step(mesh);
    const size_t n = (mesh.face_count() + s.step - 1) / s.step;
    s.faces.resize(n), s.corners.resize(n);
    parallel_for_chunked(
        n,
        [&](size_t i) {
            if (i + 16 < n)
                for (int k = 0; k < 3; ++k) __builtin_prefetch(&mesh.positions[mesh.faces[(i + 16) * s.step][k]]);
            const Face& t = mesh.faces[i * s.step];
            s.faces[i] = t;
            for (int k = 0; k < 3; ++k) s.corners[i][size_t(k)] = mesh.positions[t[k]];
        },
        4096);
    return s;
}

// A point in the coordinates of frame f (view_frame): right, up, front.
glm::vec3 in_frame(const ViewFrame& f, glm::vec3 p) { return {glm::dot(p, f.right), glm::dot(p, f.up), glm::dot(p, f.front)}; }

FaceSampling turned_into(const ViewFrame& f, FaceSampling s) {
    for (std::array<glm::vec3, 3>& c : s.corners)
        for (glm::vec3& p : c) p = in_frame(f, p);
    return s;
}

// Face centroids weighted by area, of the sampled faces with a finite
// centroid and a positive area: the samples of the front tests below.
struct FaceSample {
    glm::vec3 p;
    double w;
};
std::vector<FaceSample> face_samples(const FaceSampling& sampling) {
    std::vector<FaceSample> samples;
    for (const std::array<glm::vec3, 3>& corners : sampling.corners) {
        const glm::vec3 a = corners[0], b = corners[1], c = corners[2];
        const double w = 0.5 * glm::length(glm::cross(b - a, c - a));
        const glm::vec3 p = (a + b + c) / 3.0f;
        if (!(w > 0) || !std::isfinite(w) || !std::isfinite(p.x + p.y + p.z)) continue;
        samples.push_back({p, w});
    }
    return samples;
}

// Animals, figures and vehicles are longer than wide and carry their tallest
// parts at their front end: a head, horns, ears, a cab. The surface is
// sampled by face centroids weighted by area (face_samples). Its long
// horizontal axis is the principal axis of the xz second moments; when it is
// clearly the long one (moment ratio at least 1.5) and the top fifth of the
// model (by height) sits towards one of its ends (its centroid at least 0.2
// of the model's half-length along the axis from the whole's), that end is
// the front and the unit xz direction towards it is returned. Otherwise (a
// cube, a vase, a part with a level top) there is no front: 0.
glm::vec2 front_of_upright_model(const std::vector<FaceSample>& face_samples) {
    struct Sample { glm::dvec2 xz; float y; double w; };
    std::vector<Sample> samples;
    float y_min = INFINITY, y_max = -INFINITY;
    glm::dvec2 centroid(0);
    double total = 0;
    for (const FaceSample& fs : face_samples) {
        const glm::vec3 p = fs.p;
        const double w = fs.w;
        samples.push_back({glm::dvec2(p.x, p.z), p.y, w});
        y_min = std::min(y_min, p.y), y_max = std::max(y_max, p.y);
        centroid += w * glm::dvec2(p.x, p.z), total += w;
    }
    if (!(total > 0)) return glm::vec2(0);
    centroid /= total;
    double sxx = 0, sxz = 0, szz = 0;
    for (const Sample& s : samples) {
        const glm::dvec2 d = s.xz - centroid;
        sxx += s.w * d.x * d.x, sxz += s.w * d.x * d.y, szz += s.w * d.y * d.y;
    }
    // Eigen-decomposition of the symmetric 2x2 moment matrix.
    const double mean = 0.5 * (sxx + szz), half_gap = std::hypot(0.5 * (sxx - szz), sxz);
    const double large = mean + half_gap, small = mean - half_gap;
    if (!(large >= 1.5 * small) || !(large > 0)) return glm::vec2(0);
    const double angle = 0.5 * std::atan2(2 * sxz, sxx - szz);
    const glm::dvec2 axis(std::cos(angle), std::sin(angle));

    const float y_top = y_max - 0.2f * (y_max - y_min);
    double top = 0, w_top = 0, half_length = 0;
    for (const Sample& s : samples) {
        const double along = glm::dot(s.xz - centroid, axis);
        half_length = std::max(half_length, std::fabs(along));
        if (s.y >= y_top) top += s.w * along, w_top += s.w;
    }
    if (!(w_top > 0) || !(half_length > 0)) return glm::vec2(0);
    top /= w_top;
    if (!(std::fabs(top) >= 0.2 * half_length)) return glm::vec2(0);
    return glm::vec2(top > 0 ? axis : -axis);
}


// Flat area at the ends of each axis (choose_up, default_view.h): share of
// the surface in faces within 5 degrees of perpendicular to axis k lying in
// the slab of 2% of the extent at its low (end 0) or high (end 1) end; and
// the share of the surface in that slab whatever its faces' orientation (how
// blunt that end is).
struct UpEvidence {
    double flat[3][2] = {};
    double slab[3][2] = {};
    double extent[3] = {};
};

UpEvidence up_evidence(const Mesh& mesh, const FaceSampling& sampling) {
    UpEvidence e;
    const PositionBounds box = position_bounds(mesh.positions);
    if (box.empty()) return e;
    const glm::dvec3 lo(box.lo), hi(box.hi);
    const glm::dvec3 size = hi - lo;
    for (int k = 0; k < 3; ++k) e.extent[k] = size[k];
    const double cos_flat = std::cos(glm::radians(5.0));
    double total = 0;
    for (const std::array<glm::vec3, 3>& corners : sampling.corners) {
        const glm::dvec3 a(corners[0]), b(corners[1]), c(corners[2]);
        const glm::dvec3 n = glm::cross(b - a, c - a);
        const double w = 0.5 * glm::length(n);
        if (!(w > 0) || !std::isfinite(w)) continue;
        total += w;
        const glm::dvec3 p = (a + b + c) / 3.0;
        for (int k = 0; k < 3; ++k) {
            if (!(size[k] > 0)) continue;
            const double slab = 0.02 * size[k];
            const bool flat = std::fabs(n[k]) >= cos_flat * 2 * w;
            if (p[k] - lo[k] <= slab) e.slab[k][0] += w, e.flat[k][0] += flat ? w : 0.0;
            if (hi[k] - p[k] <= slab) e.slab[k][1] += w, e.flat[k][1] += flat ? w : 0.0;
        }
    }
    if (!(total > 0)) return UpEvidence{};
    for (int k = 0; k < 3; ++k)
        for (int end = 0; end < 2; ++end) e.flat[k][end] /= total, e.slab[k][end] /= total;
    return e;
}


// A face (default_view.h): the model is mirror-symmetric about a vertical
// plane and, along that plane's horizontal direction f, one end is pointed
// (a nose) and the other round (the back of a head). Samples: face
// centroids weighted by area (face_samples). Symmetry of a plane: the
// share of the surface whose mirror image lands in a cell of a 32-cell grid
// (on the longest side) next to a cell the surface occupies; the best of the
// planes every 5 degrees must reach 0.95. An end's bluntness: the share of
// the surface within 10% of the model's length along f of its extreme.
// Among the planes within 0.02 of the best symmetry whose one end has at
// most a third of the other's bluntness, the most symmetric: its pointed
// end is the face. Returns the unit xz direction towards it, else 0.
glm::vec2 front_of_face(const std::vector<FaceSample>& samples) {
    using Sample = FaceSample;
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    glm::dvec3 centroid(0);
    double total = 0;
    for (const Sample& s : samples) {
        lo = glm::min(lo, s.p), hi = glm::max(hi, s.p);
        centroid += s.w * glm::dvec3(s.p), total += s.w;
    }
    if (!(total > 0)) return glm::vec2(0);
    centroid /= total;
    const glm::vec3 size = hi - lo;
    const float cell = std::max({size.x, size.y, size.z}) / 32.0f;
    if (!(cell > 0) || !std::isfinite(cell)) return glm::vec2(0);
    const glm::ivec3 n = glm::min(glm::ivec3(size / cell) + 1, glm::ivec3(33));
    std::vector<uint8_t> occupied(size_t(n.x) * size_t(n.y) * size_t(n.z), 0);
    auto index = [&](glm::vec3 p, glm::ivec3& at) {
        at = glm::ivec3(glm::floor((p - lo) / cell));
        return at.x >= 0 && at.y >= 0 && at.z >= 0 && at.x < n.x && at.y < n.y && at.z < n.z;
    };
    auto flat = [&](glm::ivec3 at) { return (size_t(at.z) * size_t(n.y) + size_t(at.y)) * size_t(n.x) + size_t(at.x); };
    // Occupied cells, grown by one cell (the tolerance of the mirror test).
    for (const Sample& s : samples) {
        glm::ivec3 at;
        if (!index(s.p, at)) continue;
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const glm::ivec3 q = at + glm::ivec3(dx, dy, dz);
                    if (glm::all(glm::greaterThanEqual(q, glm::ivec3(0))) && glm::all(glm::lessThan(q, n)))
                        occupied[flat(q)] = 1;
                }
    }
    const glm::vec3 c(centroid);
    struct Plane { glm::vec2 f; double symmetry, contrast; int face; };
    std::vector<Plane> planes;
    double best_symmetry = 0;
    for (int deg = 0; deg < 180; deg += 5) {
        const float t = glm::radians(float(deg));
        const glm::vec2 f(std::sin(t), std::cos(t));
        const glm::vec3 normal(f.y, 0, -f.x);  // of the mirror plane
        double matched = 0, ext[2] = {-INFINITY, -INFINITY};
        for (const Sample& s : samples) {
            const glm::vec3 mirrored = s.p - 2 * glm::dot(s.p - c, normal) * normal;
            glm::ivec3 at;
            if (index(mirrored, at) && occupied[flat(at)]) matched += s.w;
            const double along = glm::dot(glm::vec2(s.p.x - c.x, s.p.z - c.z), f);
            ext[0] = std::max(ext[0], along), ext[1] = std::max(ext[1], -along);
        }
        const double length = ext[0] + ext[1], blunt_depth = 0.1 * length;
        double blunt[2] = {0, 0};
        for (const Sample& s : samples) {
            const double along = glm::dot(glm::vec2(s.p.x - c.x, s.p.z - c.z), f);
            if (along >= ext[0] - blunt_depth) blunt[0] += s.w;
            if (-along >= ext[1] - blunt_depth) blunt[1] += s.w;
        }
        const int face = blunt[0] <= blunt[1] ? 0 : 1;
        const double contrast = blunt[1 - face] > 0 ? blunt[face] / blunt[1 - face] : 1.0;
        planes.push_back({f, matched / total, contrast, face});
        best_symmetry = std::max(best_symmetry, matched / total);
    }
    if (!(best_symmetry >= 0.95)) return glm::vec2(0);
    const Plane* chosen = nullptr;
    for (const Plane& p : planes)
        if (p.symmetry >= best_symmetry - 0.02 && p.contrast <= 1.0 / 3.0 &&
            (!chosen || p.symmetry > chosen->symmetry))
            chosen = &p;
    if (!chosen) return glm::vec2(0);
    return chosen->face == 0 ? chosen->f : -chosen->f;
}

}  // namespace

glm::vec3 view_direction(ViewAngles a) {
    const float az = glm::radians(a.azimuth), el = glm::radians(a.elevation);
    return {std::cos(el) * std::sin(az), std::sin(el), std::cos(el) * std::cos(az)};
}

ViewFrame view_frame(glm::vec3 up) {
    const float len = glm::length(up);
    if (!(len > 0) || !std::isfinite(len)) return {};
    const glm::vec3 u = up / len;
    if (u == glm::vec3(0, 1, 0)) return {};
    ViewFrame f;
    f.up = u;
    if (u.y < -0.9999f) {  // about half a turn: about x
        f.right = glm::normalize(glm::vec3(1, 0, 0) - u.x * u);
        f.front = glm::normalize(glm::cross(f.right, u));
    } else {
        // Rodrigues: R v = v + w x v + w x (w x v) / (1 + c), w = y x u, c = y . u.
        const glm::vec3 w = glm::cross(glm::vec3(0, 1, 0), u);
        const float c = u.y;
        auto rotate = [&](glm::vec3 v) { return v + glm::cross(w, v) + glm::cross(w, glm::cross(w, v)) / (1 + c); };
        f.right = glm::normalize(rotate({1, 0, 0}));
        f.front = glm::normalize(glm::cross(f.right, u));
    }
    return f;
}

glm::vec3 view_direction(ViewAngles a, glm::vec3 up) {
    const ViewFrame f = view_frame(up);
    if (f.up == glm::vec3(0, 1, 0)) return view_direction(a);
    const glm::vec3 d = view_direction(a);
    return glm::normalize(d.x * f.right + d.y * f.up + d.z * f.front);
}

namespace {

glm::vec3 up_of(const Mesh& mesh, const FaceSampling& sampling, bool denoised) {
    const UpEvidence e = up_evidence(mesh, sampling);
    const double largest = std::max({e.extent[0], e.extent[1], e.extent[2]});
    const double base = e.flat[2][0];
    const bool long_z = e.extent[2] >= 2 * e.extent[0] && e.extent[2] >= 2 * e.extent[1];
    const bool z_up = largest > 0 && base >= (long_z ? 0.005 : 0.02) && base >= e.flat[2][1] &&
                      base >= (long_z ? 1 : 4) * std::max(e.flat[1][0], e.flat[1][1]) &&
                      base >= 2 * std::max(e.flat[0][0], e.flat[0][1]) && e.extent[2] >= 0.5 * largest;
    // A denoised scan has lost flat faces smaller than its denoising scale (a
    // figure's soles): a standing figure stands on its blunter end.
    const bool stands = denoised && long_z && e.slab[2][0] >= kBlunterEnd * e.slab[2][1];
    return z_up || stands ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
}

ViewAngles angles_in(const Mesh& mesh, const ViewFrame& frame, const FaceSampling& sampling, const VertexFaces* vf);

// The angles about frame.up; `sampling` in the mesh's own coordinates.
ViewAngles angles_about(const Mesh& mesh, const ViewFrame& frame, const FaceSampling& sampling, const VertexFaces* vf) {
    if (frame.up == glm::vec3(0, 1, 0)) return angles_in(mesh, frame, sampling, vf);
    return angles_in(mesh, frame, turned_into(frame, sampling), vf);  // the y-up rules apply as they are
}

}  // namespace

glm::vec3 choose_up(const Mesh& mesh, bool denoised) { return up_of(mesh, sample_faces(mesh), denoised); }

ViewAngles choose_default_view(const Mesh& mesh, glm::vec3 up, const VertexFaces* vf) {
    return angles_about(mesh, view_frame(up), sample_faces(mesh), vf);
}

ViewAngles choose_default_view(const Mesh& mesh, const VertexFaces* vf) {
    return angles_about(mesh, ViewFrame{}, sample_faces(mesh), vf);
}

DefaultView default_view_as_read(const Mesh& mesh, std::optional<glm::vec3> up, bool denoised,
                                 const VertexFaces* vf) {
    const FaceSampling sampling = sample_faces(mesh);  // shared by the up axis and the angles
    DefaultView v;
    const glm::vec3 u = up ? *up : up_of(mesh, sampling, denoised);
    const ViewFrame frame = view_frame(u);
    v.up = frame.up;
    v.angles = angles_about(mesh, frame, sampling, vf);
    v.eye = view_direction(v.angles, v.up);
    return v;
}

DefaultView default_view(const Mesh& mesh, std::optional<glm::vec3> up) {
    // A noisy scan is read at its noise floor: raw face normals there miss
    // flat bases and their bending is the noise's.
    const std::optional<Mesh> denoised = denoised_if_noisy(mesh);
    return default_view_as_read(denoised ? *denoised : mesh, up, denoised.has_value());
}

std::optional<glm::vec3> file_up_axis(const std::string& path) {
    const size_t dot = path.find_last_of('.');
    if (dot == std::string::npos || path.find_first_of("/\\", dot) != std::string::npos) return std::nullopt;
    std::string ext = path.substr(dot + 1);
    for (char& ch : ext) ch = char(std::tolower(static_cast<unsigned char>(ch)));
    if (ext == "gltf" || ext == "glb") return glm::vec3(0, 1, 0);
    return std::nullopt;
}

namespace {

// The angles in frame's coordinates (the y-up rules), sampling in them too.
ViewAngles angles_in(const Mesh& mesh, const ViewFrame& frame, const FaceSampling& sampling, const VertexFaces* vf) {
    const bool turned = frame.up != glm::vec3(0, 1, 0);
    auto position = [&](uint32_t v) { return turned ? in_frame(frame, mesh.positions[v]) : mesh.positions[v]; };
    // Vertex normals (area-weighted face normals, summed in face order), for how much each face bends:
    // all of them at once, or from the vertex-face rows only those of the sampled faces (below).
    auto area_normal = [&](const Face& t) {
        const glm::vec3 p0 = position(t[0]);
        return glm::cross(position(t[1]) - p0, position(t[2]) - p0);
    };
    auto summed_normal = [&](uint32_t v) {  // from the rows: the same sum, in the same order
        glm::vec3 sum(0.0f);
        for (uint32_t k = vf->begin(v); k < vf->end(v); ++k) {
            const glm::vec3 c = area_normal(mesh.faces[vf->corners[k] / 3]);
            if (std::isfinite(c.x + c.y + c.z)) sum += c;
        }
        return sum;
    };
    // Area-weighted face normals (sampled), their orientation bins and their
    // bending: how far the vertex normals turn from the face's, per unit of
    // length (a curvature, so detail draws the eye: faces, hands, ears).
    const auto dirs = bin_directions();
    const size_t samples = sampling.corners.size();
    std::vector<glm::vec3> area_normals(samples);
    std::vector<uint8_t> bin(samples);
    parallel_for_chunked(
        samples,
        [&](size_t i) {
            const std::array<glm::vec3, 3>& p = sampling.corners[i];
            const glm::vec3 c = 0.5f * glm::cross(p[1] - p[0], p[2] - p[0]);
            const float a = glm::length(c);
            int best = 0;
            for (int b = 1; b < kBins; ++b)
                if (glm::dot(c, dirs[size_t(b)]) > glm::dot(c, dirs[size_t(best)])) best = b;
            area_normals[i] = a > 0 && std::isfinite(a) ? c : glm::vec3(0.0f);
            bin[i] = uint8_t(best);
        },
        4096);
    // With the rows, when one face in 24 or fewer is sampled (meshes of 4.8M faces or more: the sampled
    // faces' corners then have about 18 / 24 of the faces around them, each fetched from anywhere, and
    // seldom share a corner): the normals of their corners alone, in parallel (the faces around the
    // corners of a face a few ahead fetched early). Otherwise every face adds its normal to its corners',
    // in one sweep.
    const bool from_rows = vf && sampling.step >= 24;
    std::vector<glm::vec3> vertex_normals;
    if (!from_rows) {
        vertex_normals.assign(mesh.vertex_count(), glm::vec3(0.0f));
        for (const Face& t : mesh.faces) {
            const glm::vec3 c = area_normal(t);
            if (!std::isfinite(c.x + c.y + c.z)) continue;
            for (int k = 0; k < 3; ++k) vertex_normals[t[k]] += c;
        }
    }
    // Each face's bending on its own.
    std::vector<float> bending(samples);
    parallel_for_chunked(
        samples,
        [&](size_t i) {
            if (area_normals[i] == glm::vec3(0.0f)) return;
            if (from_rows) {
                if (i + 16 < samples)
                    for (int k = 0; k < 3; ++k) __builtin_prefetch(&vf->corners[vf->begin(sampling.faces[i + 16][k])]);
                if (i + 8 < samples)
                    for (int k = 0; k < 3; ++k) {
                        const uint32_t v = sampling.faces[i + 8][k];
                        for (uint32_t j = vf->begin(v); j < vf->end(v); ++j) __builtin_prefetch(&mesh.faces[vf->corners[j] / 3]);
                    }
            }
            const Face& t = sampling.faces[i];
            const std::array<glm::vec3, 3>& p = sampling.corners[i];
            const glm::vec3 c = area_normals[i];
            const float a = glm::length(c);
            float turn = 0, perimeter = 0;
            for (int k = 0; k < 3; ++k) {
                const glm::vec3 n = from_rows ? summed_normal(t[k]) : vertex_normals[t[k]];
                const float ln = glm::length(n);
                if (ln > 0) turn += glm::length(n / ln - c / a);
                perimeter += glm::length(p[size_t((k + 1) % 3)] - p[size_t(k)]);
            }
            bending[i] = perimeter > 0 ? 3.0f * turn / perimeter : 0.0f;
        },
        1024);
    // The faces with an area.
    size_t kept = 0;
    for (size_t i = 0; i < samples; ++i)
        if (area_normals[i] != glm::vec3(0.0f))
            area_normals[kept] = area_normals[i], bin[kept] = bin[i], bending[kept++] = bending[i];
    area_normals.resize(kept), bin.resize(kept), bending.resize(kept);

    // Candidates in tie-breaking order.
    std::vector<ViewAngles> candidates;
    for (int k = 30; k < 180; k += 15)
        for (int sign : {1, -1})
            if (k % 90 != 0)
                for (float el : {20.0f, 35.0f}) candidates.push_back({float(sign * k), el});
    for (float el : {20.0f, 35.0f}) {
        candidates.push_back({15, el});
        candidates.push_back({-15, el});
        candidates.push_back({165, el});
        candidates.push_back({-165, el});
    }
    if (area_normals.empty()) return {30, 20};
    const std::vector<FaceSample> centroids = face_samples(sampling);
    glm::vec2 front = front_of_upright_model(centroids);
    const bool face = front == glm::vec2(0) && (front = front_of_face(centroids)) != glm::vec2(0);

    std::vector<double> entropy(candidates.size()), projected(candidates.size()), detail(candidates.size());
    parallel_for(candidates.size(), [&](size_t c) {  // each candidate on its own: the same sums on any thread
        const glm::vec3 d = view_direction(candidates[c]);
        std::array<double, kBins> weight{};
        double total = 0, bent = 0;
        for (size_t f = 0; f < area_normals.size(); ++f) {
            const double w = glm::dot(area_normals[f], d);
            if (w > 0) weight[bin[f]] += w, total += w, bent += w * bending[f];
        }
        detail[c] = bent;
        double h = 0;
        for (double w : weight)
            if (w > 0) h -= (w / total) * std::log(w / total);
        entropy[c] = total > 0 ? h / std::log(double(kBins)) : 0.0;
        projected[c] = total;
    }, 1);
    const double max_projected = std::max(0.0, *std::max_element(projected.begin(), projected.end()));
    const double max_detail = std::max(0.0, *std::max_element(detail.begin(), detail.end()));
    // Cosine between a candidate's horizontal direction and the model's front.
    auto towards_front = [&](size_t c) {
        const glm::vec3 d = view_direction(candidates[c]);
        return glm::dot(glm::normalize(glm::vec2(d.x, d.z)), front);
    };
    auto best_of = [&](float min_towards_front) {
        size_t best = 0;
        double best_score = -1;
        for (size_t c = 0; c < candidates.size(); ++c) {
            if (towards_front(c) < min_towards_front) continue;
            const double score = entropy[c] + 0.5 * (max_projected > 0 ? projected[c] / max_projected : 0.0) +
                                 kDetailWeight * (max_detail > 0 ? detail[c] / max_detail : 0.0);
            if (score > best_score + 1e-6) best = c, best_score = score;
        }
        return best;
    };
    size_t best = best_of(-1.0f);
    // Never from behind: a best view more than 120 degrees from the model's
    // front gives way to the best within 50 degrees of it.
    // A face is seen from its side: a best view more than 50 degrees from it
    // gives way likewise.
    if (front != glm::vec2(0) && towards_front(best) < (face ? 0.64f : -0.5f)) best = best_of(0.64f);
    return candidates[best];
}

}  // namespace

}  // namespace kappa
