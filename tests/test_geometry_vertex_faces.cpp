// The vertex-to-corner lists every per-vertex pass reads.
#include "geometry/parallel/parallel.h"
#include "geometry/mesh/primitives.h"
#include "geometry/mesh/vertex_faces.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

using namespace kappa;

TEST_CASE("vertex-to-corner rows list each vertex's corners in face order, whatever the thread count",
          "[topology][determinism]") {
    // Enough faces to be split into several ranges (vertex_faces.cpp), in a
    // shuffled order so that rows gather from all over the face list.
    Mesh mesh = make_icosphere(1.0f, 7);  // 327,680 faces
    std::shuffle(mesh.faces.begin(), mesh.faces.end(), std::mt19937(7));
    const size_t nv = mesh.vertex_count(), nf = mesh.face_count();
    REQUIRE(nf > 4 * 65536);

    for (unsigned threads : {1u, 2u, 3u, 4u, 7u}) {
        set_thread_count(threads);
        const VertexFaces vf = build_vertex_faces(mesh);
        REQUIRE(vf.offsets.size() == nv + 1);
        REQUIRE(vf.offsets[0] == 0);
        REQUIRE(vf.offsets[nv] == 3 * nf);
        std::vector<uint8_t> seen(3 * nf, 0);
        size_t misplaced = 0, unordered = 0;
        for (size_t v = 0; v < nv; ++v) {
            for (uint32_t k = vf.begin(v); k < vf.end(v); ++k) {
                const uint32_t c = vf.corners[k];
                misplaced += c >= 3 * nf || mesh.faces[c / 3][c % 3] != v;
                if (c < 3 * nf) ++seen[c];
                unordered += k > vf.begin(v) && vf.corners[k - 1] >= c;
            }
        }
        CAPTURE(threads);
        CHECK(misplaced == 0);
        CHECK(unordered == 0);
        CHECK(std::count(seen.begin(), seen.end(), uint8_t(1)) == std::ptrdiff_t(3 * nf));  // every corner once
    }
    set_thread_count(0);
}
