#include "mesh_topology.h"

#include "union_find.h"

#include <algorithm>

namespace kappa {

namespace {

constexpr uint32_t kNone = UINT32_MAX;

// The faces around each boundary vertex, as compressed rows in increasing
// face order; an entry's position is the id of that face's corner there.
struct BoundaryCorners {
    std::vector<uint32_t> row_of;  // per vertex: its row, kNone off the boundary
    std::vector<uint32_t> start;   // row r holds faces[start[r] .. start[r+1])
    std::vector<uint32_t> faces;

    // Id of the corner of face f at boundary vertex x (f must use x).
    uint32_t corner(uint32_t f, uint32_t x) const {
        const uint32_t r = row_of[x];
        return uint32_t(std::lower_bound(faces.begin() + start[r], faces.begin() + start[r + 1], f) -
                        faces.begin());
    }
};

BoundaryCorners boundary_corners(const Mesh& mesh, const EdgeTable& t, const std::vector<uint32_t>& boundary) {
    const size_t nv = mesh.vertex_count();
    BoundaryCorners bc;
    bc.row_of.assign(nv, kNone);
    uint32_t rows = 0;
    for (uint32_t e : boundary)
        for (uint32_t x : {t.ends[e].x, t.ends[e].y})
            if (bc.row_of[x] == kNone) bc.row_of[x] = rows++;
    bc.start.assign(rows + 1, 0);
    for (const Face& f : mesh.faces)
        if (is_valid_face(f, nv))
            for (int i = 0; i < 3; ++i)
                if (bc.row_of[f[i]] != kNone) ++bc.start[bc.row_of[f[i]] + 1];
    for (uint32_t r = 0; r < rows; ++r) bc.start[r + 1] += bc.start[r];
    bc.faces.resize(bc.start[rows]);
    std::vector<uint32_t> fill(bc.start.begin(), bc.start.end() - 1);
    for (uint32_t fi = 0; fi < mesh.face_count(); ++fi) {
        const Face& f = mesh.faces[fi];
        if (is_valid_face(f, nv))
            for (int i = 0; i < 3; ++i)
                if (bc.row_of[f[i]] != kNone) bc.faces[fill[bc.row_of[f[i]]]++] = fi;
    }
    return bc;
}

}  // namespace

size_t count_boundary_loops(const Mesh& mesh, const EdgeTable& t) {
    std::vector<uint32_t> boundary;
    for (size_t e = 0; e < t.size(); ++e)
        if (t.face_count(e) == 1) boundary.push_back(uint32_t(e));
    if (boundary.empty()) return 0;

    // Wedges: corners at a boundary vertex joined across its two-face edges.
    const BoundaryCorners bc = boundary_corners(mesh, t, boundary);
    UnionFind wedges(bc.faces.size());
    for (size_t e = 0; e < t.size(); ++e) {
        if (t.face_count(e) != 2) continue;
        const uint32_t f0 = t.halfedges[t.first[e]] / 3, f1 = t.halfedges[t.first[e] + 1] / 3;
        for (uint32_t x : {t.ends[e].x, t.ends[e].y})
            if (bc.row_of[x] != kNone) wedges.unite(bc.corner(f0, x), bc.corner(f1, x));
    }

    // Each boundary edge ends in one wedge at each of its two vertices; a
    // wedge holding two boundary-edge ends makes those edges consecutive.
    std::vector<uint64_t> wedge_ends;  // (wedge, index into `boundary`)
    wedge_ends.reserve(2 * boundary.size());
    for (uint32_t k = 0; k < boundary.size(); ++k) {
        const uint32_t e = boundary[k], f = t.halfedges[t.first[e]] / 3;
        for (uint32_t x : {t.ends[e].x, t.ends[e].y})
            wedge_ends.push_back((uint64_t(wedges.find(bc.corner(f, x))) << 32) | k);
    }
    std::sort(wedge_ends.begin(), wedge_ends.end());

    UnionFind chains(boundary.size());
    size_t loops = boundary.size();
    for (size_t i = 0; i + 1 < wedge_ends.size(); ++i)
        if ((wedge_ends[i] >> 32) == (wedge_ends[i + 1] >> 32) &&
            chains.unite(uint32_t(wedge_ends[i]), uint32_t(wedge_ends[i + 1])))
            --loops;
    return loops;
}

Components find_components(const Mesh& mesh) {
    const size_t nv = mesh.vertex_count();
    UnionFind sets(nv);
    std::vector<uint8_t> used(nv, 0);
    for (const Face& f : mesh.faces) {
        if (f[0] >= nv || f[1] >= nv || f[2] >= nv) continue;
        sets.unite(f[0], f[1]);
        sets.unite(f[0], f[2]);
        used[f[0]] = used[f[1]] = used[f[2]] = 1;
    }
    Components c;
    c.label.assign(nv, kNoComponent);
    std::vector<uint32_t> label_of_root(nv, kNoComponent);
    for (size_t v = 0; v < nv; ++v) {
        if (!used[v]) {
            ++c.isolated_vertices;
            continue;
        }
        uint32_t& root_label = label_of_root[sets.find(uint32_t(v))];
        if (root_label == kNoComponent) root_label = uint32_t(c.count++);
        c.label[v] = root_label;
    }
    return c;
}

Topology analyze_topology(const Mesh& mesh, const EdgeTable& t) {
    const size_t nv = mesh.vertex_count();
    Topology topo;
    std::vector<uint8_t> on_surface(nv, 0);
    for (const Face& f : mesh.faces)
        if (is_valid_face(f, nv)) {
            ++topo.valid_faces;
            on_surface[f[0]] = on_surface[f[1]] = on_surface[f[2]] = 1;
        }
    topo.surface_vertices = size_t(std::count(on_surface.begin(), on_surface.end(), uint8_t(1)));
    topo.edges = t.size();
    for (size_t e = 0; e < t.size(); ++e) {
        topo.boundary_edges += t.face_count(e) == 1;
        topo.nonmanifold_edges += t.face_count(e) > 2;
    }
    topo.boundary_loops = count_boundary_loops(mesh, t);
    const Components components = find_components(mesh);
    topo.components = components.count;
    topo.isolated_vertices = components.isolated_vertices;
    topo.euler_characteristic =
        (long long)topo.surface_vertices - (long long)topo.edges + (long long)topo.valid_faces;
    return topo;
}

}  // namespace kappa
