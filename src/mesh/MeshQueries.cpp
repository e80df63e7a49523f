#include "mesh/MeshQueries.hpp"

#include <cmath>

namespace ma {

int vertexCount(CellType t) {
    switch (t) {
        case CellType::POI1: return 1;
        case CellType::SEG2:
        case CellType::SEG3:
        case CellType::SEG4: return 2;
        case CellType::TRIA3:
        case CellType::TRIA6:
        case CellType::TRIA7: return 3;
        case CellType::QUAD4:
        case CellType::QUAD8:
        case CellType::QUAD9: return 4;
        case CellType::TETRA4:
        case CellType::TETRA10: return 4;
        case CellType::PYRA5:
        case CellType::PYRA13: return 5;
        case CellType::PENTA6:
        case CellType::PENTA15:
        case CellType::PENTA18: return 6;
        case CellType::HEXA8:
        case CellType::HEXA20:
        case CellType::HEXA27: return 8;
    }
    return nodeCount(t);
}

int centreNodeCount(CellType t) {
    switch (t) {
        case CellType::TRIA7:
        case CellType::QUAD9: return 1;
        case CellType::PENTA18: return 3;
        case CellType::HEXA27: return 7;
        default: return 0;
    }
}

int effectiveDimension(const Mesh& mesh) {
    if (mesh.dim == 2 || mesh.coords.empty()) return 2;
    const double z0 = mesh.coords.front()[2];
    for (const auto& x : mesh.coords)
        if (x[2] != z0) return 3;
    return 2;
}

Vec3 vertexCentroid(const Mesh& mesh, int cell) {
    auto nodes = mesh.cellNodes(cell);
    const int nv = vertexCount(mesh.cellTypes[size_t(cell)]);
    Vec3 g{0, 0, 0};
    for (int k = 0; k < nv; ++k)
        for (int d = 0; d < 3; ++d) g[size_t(d)] += mesh.coords[size_t(nodes[size_t(k)])][size_t(d)];
    for (auto& v : g) v /= nv;
    return g;
}

Vec3 cellNormal(const Mesh& mesh, int cell) {
    const CellType t = mesh.cellTypes[size_t(cell)];
    auto nodes = mesh.cellNodes(cell);
    const auto& p1 = mesh.coords[size_t(nodes[0])];
    if (cellDimension(t) == 1) {
        const auto& p2 = mesh.coords[size_t(nodes[1])];
        return {p2[1] - p1[1], -(p2[0] - p1[0]), 0.0};
    }
    if (cellDimension(t) == 2) {
        const auto& p2 = mesh.coords[size_t(nodes[1])];
        const auto& p3 = mesh.coords[size_t(nodes[2])];
        return cross(difference(p2, p1), difference(p3, p1));
    }
    return {0, 0, 0};
}

NodeCellIndex::NodeCellIndex(const Mesh& mesh, int dim, const std::vector<int>& cells) {
    auto each = [&](auto&& visit) {
        const int n = cells.empty() ? mesh.cellCount() : int(cells.size());
        for (int i = 0; i < n; ++i) {
            const int c = cells.empty() ? i : cells[size_t(i)];
            if (cellDimension(mesh.cellTypes[size_t(c)]) == dim) visit(c);
        }
    };
    start_.assign(size_t(mesh.nodeCount()) + 1, 0);
    each([&](int c) {
        for (int v : mesh.cellNodes(c)) ++start_[size_t(v) + 1];
    });
    for (size_t i = 1; i < start_.size(); ++i) start_[i] += start_[i - 1];
    cells_.resize(size_t(start_.back()));
    std::vector<int> fill(start_.begin(), start_.end() - 1);
    each([&](int c) {
        for (int v : mesh.cellNodes(c)) cells_[size_t(fill[size_t(v)]++)] = c;
    });
}

}  // namespace ma
