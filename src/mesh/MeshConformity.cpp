#include "mesh/MeshConformity.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <tuple>

#include "core/Vec3.hpp"
#include "mesh/MeshQueries.hpp"

namespace ma {
namespace {

using Face = std::vector<int>;  // local vertex indices of a face (3D) or an edge (2D)

const std::vector<Face>& localFaces(CellType t) {
    static const std::vector<Face> tria{{0, 1}, {1, 2}, {2, 0}}, quad{{0, 1}, {1, 2}, {2, 3}, {3, 0}},
        tetra{{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}},
        pyra{{0, 1, 2, 3}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}},
        penta{{0, 1, 2}, {3, 4, 5}, {0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}},
        hexa{{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}, none;
    switch (vertexCount(t) + 100 * cellDimension(t)) {
        case 203: return tria;
        case 204: return quad;
        case 304: return tetra;
        case 305: return pyra;
        case 306: return penta;
        case 308: return hexa;
        default: return none;
    }
}

struct CellFace {
    int cell = 0, local = 0;
};

bool containsAll(std::span<const int> cellNodes, std::span<const int> nodes, const Face& face) {
    for (int v : face)
        if (std::find(cellNodes.begin(), cellNodes.end(), nodes[size_t(v)]) == cellNodes.end()) return false;
    return true;
}

// Faces of one cell only: no other cell of the dimension holds all their nodes.
std::vector<CellFace> unsharedFaces(const Mesh& mesh, int dim) {
    const NodeCellIndex around(mesh, dim);
    std::vector<CellFace> once;
    for (int c = 0; c < mesh.cellCount(); ++c) {
        if (cellDimension(mesh.cellTypes[size_t(c)]) != dim) continue;
        const auto nodes = mesh.cellNodes(c);
        const auto& faces = localFaces(mesh.cellTypes[size_t(c)]);
        for (size_t f = 0; f < faces.size(); ++f) {
            bool shared = false;
            for (const int d : around.cellsOf(nodes[size_t(faces[f][0])]))
                if (d != c && containsAll(mesh.cellNodes(d), nodes, faces[f])) shared = true;
            if (!shared) once.push_back({c, int(f)});
        }
    }
    return once;
}

// The face's nodes in the cell's order (a polygon, or a segment in 2D).
std::vector<Vec3> facePoints(const Mesh& mesh, const CellFace& f) {
    const auto nodes = mesh.cellNodes(f.cell);
    std::vector<Vec3> p;
    for (int v : localFaces(mesh.cellTypes[size_t(f.cell)])[size_t(f.local)])
        p.push_back(mesh.coords[size_t(nodes[size_t(v)])]);
    return p;
}

Vec3 centroid(const std::vector<Vec3>& p) {
    Vec3 c{0, 0, 0};
    for (const auto& q : p)
        for (int k = 0; k < 3; ++k) c[size_t(k)] += q[size_t(k)] / double(p.size());
    return c;
}

// Two unshared faces with a common edge (2D: a common node) overlap when they lie in one plane
// (on one line) on the same side of that edge (node): the two sides of a badly split face.
bool overlap(const Mesh& mesh, const CellFace& a, const CellFace& b, const Vec3& p, const Vec3& q, int dim) {
    const auto pa = facePoints(mesh, a), pb = facePoints(mesh, b);
    const Vec3 ca = difference(centroid(pa), p), cb = difference(centroid(pb), p);
    if (dim == 2) {  // segments from the common node p: collinear and pointing the same way
        const double c = cross(ca, cb)[2];
        return std::abs(c) <= 1e-8 * norm(ca) * norm(cb) && dot(ca, cb) > 0;
    }
    const Vec3 e = difference(q, p);
    const Vec3 na = cross(e, ca), nb = cross(e, cb);  // each face's normal, from the common edge
    return norm(cross(na, nb)) <= 1e-8 * norm(na) * norm(nb) && dot(na, nb) > 0;
}

}  // namespace

ConformityReport meshConformity(const Mesh& mesh) {
    ConformityReport r;
    for (int c = 0; c < mesh.cellCount(); ++c)
        r.dimension = std::max(r.dimension, cellDimension(mesh.cellTypes[size_t(c)]));
    if (r.dimension < 2) return r;
    const auto once = unsharedFaces(mesh, r.dimension);
    r.unsharedFaces = int(once.size());
    // Sub-faces (3D: edges, 2D: nodes) of the unshared faces, sorted to meet the faces sharing one.
    struct Sub {
        int a, b, face;
    };
    std::vector<Sub> subs;
    for (size_t i = 0; i < once.size(); ++i) {
        const auto& local = localFaces(mesh.cellTypes[size_t(once[i].cell)])[size_t(once[i].local)];
        const auto nodes = mesh.cellNodes(once[i].cell);
        for (size_t k = 0; k < local.size(); ++k) {
            int a = nodes[size_t(local[k])], b = r.dimension == 3 ? nodes[size_t(local[(k + 1) % local.size()])] : a;
            if (r.dimension == 3 && a > b) std::swap(a, b);
            subs.push_back({a, b, int(i)});
        }
    }
    std::sort(subs.begin(), subs.end(),
              [](const Sub& x, const Sub& y) { return std::tie(x.a, x.b) < std::tie(y.a, y.b); });
    std::vector<char> faulty(once.size(), 0);
    for (size_t i = 0; i < subs.size();) {
        size_t j = i + 1;
        while (j < subs.size() && subs[j].a == subs[i].a && subs[j].b == subs[i].b) ++j;
        const Vec3& p = mesh.coords[size_t(subs[i].a)];
        const Vec3& q = mesh.coords[size_t(subs[i].b)];
        for (size_t u = i; u < j; ++u)
            for (size_t v = u + 1; v < j; ++v)
                if (overlap(mesh, once[size_t(subs[u].face)], once[size_t(subs[v].face)], p, q, r.dimension))
                    faulty[size_t(subs[u].face)] = faulty[size_t(subs[v].face)] = 1;
        i = j;
    }
    for (size_t i = 0; i < once.size(); ++i)
        if (faulty[i]) ++r.overlappingFaces, r.faultCells.push_back(once[i].cell);
    std::sort(r.faultCells.begin(), r.faultCells.end());
    r.faultCells.erase(std::unique(r.faultCells.begin(), r.faultCells.end()), r.faultCells.end());
    return r;
}

}  // namespace ma
