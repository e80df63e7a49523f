#include "xfem/CellGeometry.hpp"

#include <cmath>

#include "core/Error.hpp"
#include "core/Vec3.hpp"
#include "mesh/ShapeFunctions.hpp"

namespace ma::xfem {

namespace {
constexpr std::array<Edge, 1> kSeg2{{{0, 1}}};
constexpr std::array<Edge, 3> kTria3{{{0, 1}, {1, 2}, {2, 0}}};
constexpr std::array<Edge, 4> kQuad4{{{0, 1}, {1, 2}, {2, 3}, {3, 0}}};
constexpr std::array<Edge, 6> kTetra4{{{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}}};
constexpr std::array<Edge, 12> kHexa8{
    {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 5}, {2, 6}, {3, 7}, {4, 5}, {5, 6}, {6, 7}, {7, 4}}};

[[noreturn]] void unsupported(CellType type) {
    throw NotImplemented("X-FEM elements are not available on " + cellTypeName(type) +
                         " cells (SEG2, TRIA3, QUAD4, TETRA4 and HEXA8 only)");
}
}  // namespace

// The linear cells of the elasticity engine (those with shape functions).
bool xfemSupports(CellType type) { return hasShapeFunctions(type); }

std::span<const Edge> cellEdges(CellType type) {
    switch (type) {
        case CellType::SEG2: return kSeg2;
        case CellType::TRIA3: return kTria3;
        case CellType::QUAD4: return kQuad4;
        case CellType::TETRA4: return kTetra4;
        case CellType::HEXA8: return kHexa8;
        default: unsupported(type);
    }
}

std::vector<std::vector<int>> primarySimplices(CellType type) {
    switch (type) {
        case CellType::SEG2: return {{0, 1}};
        case CellType::TRIA3: return {{0, 1, 2}};
        case CellType::QUAD4: return {{0, 1, 3}, {1, 2, 3}};
        case CellType::TETRA4: return {{0, 1, 2, 3}};
        // code_aster's connectivity (6,3,2,4), (4,5,1,2), (2,5,6,4), (5,4,8,6), (3,6,7,8), (3,8,4,6).
        case CellType::HEXA8:
            return {{5, 2, 1, 3}, {3, 4, 0, 1}, {1, 4, 5, 3}, {4, 3, 7, 5}, {2, 5, 6, 7}, {2, 7, 3, 5}};
        default: unsupported(type);
    }
}

CellType simplexType(CellType type) {
    switch (cellDimension(type)) {
        case 1: return CellType::SEG2;
        case 2: return CellType::TRIA3;
        case 3: return CellType::TETRA4;
        default: unsupported(type);
    }
}

double simplexMeasure(int dim, std::span<const std::array<double, 3>> v) {
    if (dim == 1) {
        double l2 = 0;
        for (int j = 0; j < 3; ++j) l2 += (v[1][j] - v[0][j]) * (v[1][j] - v[0][j]);
        return std::sqrt(l2);
    }
    const double ax = v[1][0] - v[0][0], ay = v[1][1] - v[0][1], az = v[1][2] - v[0][2];
    const double bx = v[2][0] - v[0][0], by = v[2][1] - v[0][1], bz = v[2][2] - v[0][2];
    if (dim == 2) return 0.5 * (ax * by - ay * bx);
    const double cx = v[3][0] - v[0][0], cy = v[3][1] - v[0][1], cz = v[3][2] - v[0][2];
    return (ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx)) / 6.0;
}

double characteristicLength(const Mesh& mesh, int cell) {
    const auto nodes = mesh.cellNodes(cell);
    auto d = [&](int a, int b) {
        return distance(mesh.coords[size_t(nodes[size_t(a)])], mesh.coords[size_t(nodes[size_t(b)])]);
    };
    switch (mesh.cellTypes[size_t(cell)]) {
        case CellType::SEG2: return d(0, 1);
        case CellType::HEXA8: return d(0, 6);
        case CellType::TETRA4: return std::cbrt(d(0, 1) * d(0, 2) * d(0, 3));
        case CellType::QUAD4:
        case CellType::TRIA3: return std::sqrt(d(0, 1) * d(0, 2));
        default: throw NotImplemented("characteristic length of cell " + mesh.cellNames[size_t(cell)]);
    }
}

}  // namespace ma::xfem
