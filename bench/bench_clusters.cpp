// Face clusters and their culling bounds (geometry/culling/face_clusters.h,
// geometry/culling/cluster_bounds.h): the once-per-mesh cost of cluster_faces and
// compute_cluster_bounds (single-threaded), the per-frame cost of classifying
// every cluster, and how many clusters / faces the default camera culls. Beside
// them, the rest of the buffers' once-per-mesh layout that walks the vertex-face
// rows (render/fields/mesh_buffers.h): where back faces can be seen
// (geometry/culling/back_faces.h), with the rows and orientation given as a drawing has them.
// Prints every run and the median.
//
//   bench_clusters [MESH] [RUNS] [MAX_FACES]   (default: ../shared/meshes/bunny-1M.ply next to the repo, 11 runs, 256)
#include "time_it.h"

#include "geometry/culling/back_faces.h"
#include "geometry/culling/cluster_bounds.h"
#include "geometry/culling/face_clusters.h"
#include "geometry/curvature/face_geometry.h"
#include "geometry/io/mesh_io.h"
#include "geometry/curvature/vertex_basics.h"
#include "geometry/mesh/vertex_faces.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

using kappa::bench::time_it;

int main(int argc, char** argv) {
    const std::filesystem::path source_dir = std::filesystem::path(__FILE__).parent_path().parent_path();
    const std::string path =
        argc > 1 ? argv[1] : (source_dir / ".." / "shared" / "meshes" / "bunny-1M.ply").string();
    const int runs = argc > 2 ? std::max(1, std::atoi(argv[2])) : 11;
    const uint32_t max_faces = argc > 3 ? uint32_t(std::max(1, std::atoi(argv[3]))) : 256;
    const kappa::Mesh mesh = kappa::load_mesh(path);
    std::printf("%s: %zu vertices, %zu faces, max %u faces per cluster\n", path.c_str(), mesh.vertex_count(),
                mesh.face_count(), max_faces);

    const std::vector<glm::vec3> normals =
        kappa::compute_vertex_basics(kappa::build_vertex_faces(mesh), kappa::compute_face_geometry(mesh)).normals;
    const kappa::FaceClusters clusters = kappa::cluster_faces(mesh, max_faces);
    const std::vector<kappa::ClusterBounds> bounds = kappa::compute_cluster_bounds(mesh, normals, clusters);
    time_it("cluster_faces", runs, [&] { kappa::cluster_faces(mesh, max_faces); });
    const kappa::VertexFaces rows = kappa::build_vertex_faces(mesh);
    time_it("cluster_faces (rows given)", runs, [&] { kappa::cluster_faces(mesh, max_faces, &rows); });
    time_it("back_face_visibility (rows, orientation given)", runs,
            [&] { kappa::back_face_visibility(mesh, rows, true); });
    time_it("compute_cluster_bounds", runs, [&] { kappa::compute_cluster_bounds(mesh, normals, clusters); });
    time_it("both", runs, [&] { kappa::compute_cluster_bounds(mesh, normals, kappa::cluster_faces(mesh, max_faces)); });

    // The renderer's default view: from +z, at the bounding sphere's centre
    // (bounding-box centre, radius to the farthest vertex) plus z * radius.
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    for (const glm::vec3& p : mesh.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const glm::vec3 center = 0.5f * (lo + hi);
    float radius = 0;
    for (const glm::vec3& p : mesh.positions) radius = std::max(radius, glm::length(p - center));
    size_t sink = 0;
    time_it("classify_facing, all", runs, [&] {
        for (const kappa::ClusterBounds& b : bounds)
            sink += kappa::classify_facing(b, center + glm::vec3(0, 0, 2.2f * radius)) == kappa::Facing::Mixed;
    });

    std::printf("%zu clusters (%.1f faces each on average)\n", clusters.size(),
                double(mesh.face_count()) / double(std::max<size_t>(clusters.size(), 1)));
    // 3.86 = 1 / sin(15 deg): Camera::framing with the default 30 deg field of view, 1024x768.
    for (float z : {2.2f, 3.86f, 10.0f}) {
        const glm::vec3 eye = center + glm::vec3(0, 0, z * radius);
        size_t count[3] = {0, 0, 0}, faces[3] = {0, 0, 0};
        for (size_t c = 0; c < clusters.size(); ++c) {
            const int k = int(kappa::classify_facing(bounds[c], eye));
            ++count[k];
            faces[k] += clusters.cluster_start[c + 1] - clusters.cluster_start[c];
        }
        const double nc = double(clusters.size()), nf = double(mesh.face_count());
        std::printf("eye at centre + (0, 0, %.2f r): clusters front %.1f%% back %.1f%% mixed %.1f%%"
                    " | faces front %.1f%% back %.1f%% mixed %.1f%%\n",
                    z, 100 * count[0] / nc, 100 * count[1] / nc, 100 * count[2] / nc, 100 * faces[0] / nf,
                    100 * faces[1] / nf, 100 * faces[2] / nf);
    }
    return sink == size_t(-1);
}
