#include "mesh/ShapeFunctions.hpp"

#include <cmath>

#include "core/Error.hpp"
#include "mesh/ElementGeometry.hpp"

namespace ma {

namespace {
constexpr std::array<std::array<double, 3>, 2> kSeg2{{{-1, 0, 0}, {1, 0, 0}}};
constexpr std::array<std::array<double, 3>, 3> kTria3{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}};
constexpr std::array<std::array<double, 3>, 4> kQuad4{{{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}};
constexpr std::array<std::array<double, 3>, 4> kTetra4{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
constexpr std::array<std::array<double, 3>, 8> kHexa8{
    {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}}};

[[noreturn]] void unsupported(CellType type) {
    throw NotImplemented("no shape functions for cell type " + cellTypeName(type));
}
}  // namespace

bool hasShapeFunctions(CellType type) {
    switch (type) {
        case CellType::SEG2:
        case CellType::TRIA3:
        case CellType::QUAD4:
        case CellType::TETRA4:
        case CellType::HEXA8: return true;
        default: return false;
    }
}

int referenceDimension(CellType type) { return cellDimension(type); }

std::span<const std::array<double, 3>> referenceNodes(CellType type) {
    switch (type) {
        case CellType::SEG2: return kSeg2;
        case CellType::TRIA3: return kTria3;
        case CellType::QUAD4: return kQuad4;
        case CellType::TETRA4: return kTetra4;
        case CellType::HEXA8: return kHexa8;
        default: unsupported(type);
    }
}

void shapeValues(CellType type, const std::array<double, 3>& xi, std::span<double> N) {
    const double x = xi[0], y = xi[1], z = xi[2];
    switch (type) {
        case CellType::SEG2:
            N[0] = 0.5 * (1 - x);
            N[1] = 0.5 * (1 + x);
            return;
        case CellType::TRIA3:
            N[0] = 1 - x - y;
            N[1] = x;
            N[2] = y;
            return;
        case CellType::QUAD4:
            for (int a = 0; a < 4; ++a) N[a] = 0.25 * (1 + kQuad4[a][0] * x) * (1 + kQuad4[a][1] * y);
            return;
        case CellType::TETRA4:
            N[0] = 1 - x - y - z;
            N[1] = x;
            N[2] = y;
            N[3] = z;
            return;
        case CellType::HEXA8:
            for (int a = 0; a < 8; ++a)
                N[a] = 0.125 * (1 + kHexa8[a][0] * x) * (1 + kHexa8[a][1] * y) * (1 + kHexa8[a][2] * z);
            return;
        default: unsupported(type);
    }
}

void shapeDerivatives(CellType type, const std::array<double, 3>& xi, std::span<double> dN) {
    const double x = xi[0], y = xi[1], z = xi[2];
    const int n = nodeCount(type);
    for (int i = 0; i < 3 * n; ++i) dN[i] = 0.0;
    switch (type) {
        case CellType::SEG2:
            dN[0] = -0.5;
            dN[3] = 0.5;
            return;
        case CellType::TRIA3:
            dN[0] = -1, dN[1] = -1;
            dN[3] = 1;
            dN[7] = 1;
            return;
        case CellType::QUAD4:
            for (int a = 0; a < 4; ++a) {
                const double sx = kQuad4[a][0], sy = kQuad4[a][1];
                dN[3 * a] = 0.25 * sx * (1 + sy * y);
                dN[3 * a + 1] = 0.25 * sy * (1 + sx * x);
            }
            return;
        case CellType::TETRA4:
            dN[0] = dN[1] = dN[2] = -1;
            dN[3] = 1;
            dN[7] = 1;
            dN[11] = 1;
            return;
        case CellType::HEXA8:
            for (int a = 0; a < 8; ++a) {
                const double sx = kHexa8[a][0], sy = kHexa8[a][1], sz = kHexa8[a][2];
                dN[3 * a] = 0.125 * sx * (1 + sy * y) * (1 + sz * z);
                dN[3 * a + 1] = 0.125 * sy * (1 + sx * x) * (1 + sz * z);
                dN[3 * a + 2] = 0.125 * sz * (1 + sx * x) * (1 + sy * y);
            }
            return;
        default: unsupported(type);
    }
}

std::array<double, 3> mapToPhysical(CellType type, std::span<const std::array<double, 3>> nodes,
                                    const std::array<double, 3>& xi) {
    std::array<double, 8> N{};
    shapeValues(type, xi, N);
    std::array<double, 3> x{};
    for (size_t a = 0; a < nodes.size(); ++a)
        for (int j = 0; j < 3; ++j) x[j] += N[a] * nodes[a][j];
    return x;
}

bool mapToReference(CellType type, std::span<const std::array<double, 3>> nodes, const std::array<double, 3>& x,
                    std::array<double, 3>& xi) {
    const int d = referenceDimension(type);
    if (d < 2) unsupported(type);
    const int n = nodeCount(type);
    // Coordinates from the first node: the stopping test is relative to the cell's size, which the
    // round-off of coordinates far from the origin (a cell of 1e-2 at 0.25) would not let it reach.
    std::array<std::array<double, 3>, 27> local{};
    double size = 0.0;
    for (int a = 0; a < n; ++a)
        for (int j = 0; j < 3; ++j) {
            local[size_t(a)][size_t(j)] = nodes[size_t(a)][size_t(j)] - nodes[0][size_t(j)];
            size = std::max(size, std::abs(local[size_t(a)][size_t(j)]));
        }
    const std::span<const std::array<double, 3>> corners(local.data(), size_t(n));
    const std::array<double, 3> target{x[0] - nodes[0][0], x[1] - nodes[0][1], x[2] - nodes[0][2]};
    xi = {0, 0, 0};
    if (type == CellType::TRIA3) xi = {1.0 / 3, 1.0 / 3, 0};
    if (type == CellType::TETRA4) xi = {0.25, 0.25, 0.25};
    std::array<double, 24> dN{};
    for (int it = 0; it < 50; ++it) {
        const auto cur = mapToPhysical(type, corners, xi);
        shapeDerivatives(type, xi, dN);
        double J[3][3] = {}, inv[3][3] = {};
        jacobian(
            d, d, n, [&](int a) -> const Vec3& { return corners[size_t(a)]; },
            [&](int a, int j) { return dN[3 * a + j]; }, J);
        const Vec3 r{target[0] - cur[0], target[1] - cur[1], d == 3 ? target[2] - cur[2] : 0.0};
        if (norm(r) <= 1e-15 * size) return true;
        if (invertJacobian(d, J, inv) == 0.0) return false;
        Vec3 step{};  // J^-1 r
        for (int i = 0; i < d; ++i)
            for (int j = 0; j < d; ++j) step[i] += inv[i][j] * r[j];
        for (int j = 0; j < d; ++j) xi[j] += step[j];
        if (norm(step) <= 1e-15) return true;
    }
    return false;
}

}  // namespace ma
