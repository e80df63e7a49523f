#include "mesh/PointLocation.hpp"

#include <algorithm>
#include <cmath>

#include "mesh/ShapeFunctions.hpp"

namespace ma {

namespace {

constexpr double kInside = 1e-10;  // reference coordinates: a fraction of the cell's size

bool insideReference(CellType type, const std::array<double, 3>& xi, int d) {
    if (type == CellType::TRIA3 || type == CellType::TETRA4) {
        double sum = 0.0;
        for (int j = 0; j < d; ++j) {
            if (xi[size_t(j)] < -kInside) return false;
            sum += xi[size_t(j)];
        }
        return sum <= 1.0 + kInside;
    }
    for (int j = 0; j < d; ++j)
        if (std::abs(xi[size_t(j)]) > 1.0 + kInside) return false;
    return true;
}

// The cell's bounding box widened by kInside of its size contains x (in the first d coordinates).
bool inBox(std::span<const std::array<double, 3>> nodes, const Vec3& x, int d) {
    for (int j = 0; j < d; ++j) {
        double lo = nodes[0][size_t(j)], hi = lo;
        for (const auto& p : nodes) lo = std::min(lo, p[size_t(j)]), hi = std::max(hi, p[size_t(j)]);
        const double margin = kInside * (hi - lo);
        if (x[j] < lo - margin || x[j] > hi + margin) return false;
    }
    return true;
}

}  // namespace

PointInCell locatePoint(const Mesh& mesh, const Vec3& x) {
    const int dim = mesh.maxCellDimension();
    std::vector<std::array<double, 3>> nodes;
    for (int c = 0; c < mesh.cellCount(); ++c) {
        const CellType type = mesh.cellTypes[size_t(c)];
        if (cellDimension(type) != dim || dim < 2 || !hasShapeFunctions(type)) continue;
        nodes.clear();
        for (int n : mesh.cellNodes(c)) nodes.push_back(mesh.coords[size_t(n)]);
        if (!inBox(nodes, x, dim)) continue;
        std::array<double, 3> xi{};
        if (mapToReference(type, nodes, {x[0], x[1], mesh.dim == 3 ? x[2] : 0.0}, xi) && insideReference(type, xi, dim))
            return {c, xi};
    }
    return {};
}

namespace {

// xi moved to the nearest point of the reference element (a simplex's excess spread evenly).
void clampToReference(CellType type, std::array<double, 3>& xi, int d) {
    if (type == CellType::TRIA3 || type == CellType::TETRA4) {
        double sum = 0.0;
        for (int j = 0; j < d; ++j) sum += (xi[size_t(j)] = std::max(xi[size_t(j)], 0.0));
        if (sum > 1.0)
            for (int j = 0; j < d; ++j) xi[size_t(j)] /= sum;
        return;
    }
    for (int j = 0; j < d; ++j) xi[size_t(j)] = std::clamp(xi[size_t(j)], -1.0, 1.0);
}

}  // namespace

PointInCell locateNearPoint(const Mesh& mesh, const Vec3& x, double maxDistance) {
    const PointInCell inside = locatePoint(mesh, x);
    if (inside.cell >= 0 || !(maxDistance > 0)) return inside;
    const int dim = mesh.maxCellDimension();
    PointInCell best;
    double nearest = maxDistance;
    std::vector<std::array<double, 3>> nodes;
    std::array<double, 27> N{};
    for (int c = 0; c < mesh.cellCount(); ++c) {
        const CellType type = mesh.cellTypes[size_t(c)];
        if (cellDimension(type) != dim || dim < 2 || !hasShapeFunctions(type)) continue;
        nodes.clear();
        for (int n : mesh.cellNodes(c)) nodes.push_back(mesh.coords[size_t(n)]);
        bool near = true;
        for (int j = 0; j < dim; ++j) {
            double lo = nodes[0][size_t(j)], hi = lo;
            for (const auto& p : nodes) lo = std::min(lo, p[size_t(j)]), hi = std::max(hi, p[size_t(j)]);
            near = near && x[j] >= lo - maxDistance && x[j] <= hi + maxDistance;
        }
        if (!near) continue;
        // Relative to the cell's first node, as mapToReference works: the distance below is then
        // round-off of the cell's size, not of the coordinates'.
        const Vec3 origin = nodes[0];
        for (auto& p : nodes) p = difference(p, origin);
        const Vec3 target = difference({x[0], x[1], mesh.dim == 3 ? x[2] : 0.0}, origin);
        std::array<double, 3> xi{};
        if (!mapToReference(type, nodes, target, xi)) continue;
        clampToReference(type, xi, dim);
        shapeValues(type, xi, N);
        Vec3 y{};
        for (size_t a = 0; a < nodes.size(); ++a)
            for (size_t j = 0; j < 3; ++j) y[j] += N[a] * nodes[a][j];
        const double d = distance(y, target);
        if (d < nearest) nearest = d, best = {c, xi};
    }
    return best;
}

double interpolateAt(const Mesh& mesh, const PointInCell& at, const std::vector<double>& values) {
    const auto nodes = mesh.cellNodes(at.cell);
    std::array<double, 27> N{};
    shapeValues(mesh.cellTypes[size_t(at.cell)], at.xi, N);
    double v = 0.0;
    for (size_t a = 0; a < nodes.size(); ++a) v += N[a] * values[size_t(nodes[a])];
    return v;
}

Vec3 interpolateAt(const Mesh& mesh, const PointInCell& at, const std::vector<Vec3>& values) {
    const auto nodes = mesh.cellNodes(at.cell);
    std::array<double, 27> N{};
    shapeValues(mesh.cellTypes[size_t(at.cell)], at.xi, N);
    Vec3 v{};
    for (size_t a = 0; a < nodes.size(); ++a)
        for (size_t c = 0; c < 3; ++c) v[c] += N[a] * values[size_t(nodes[a])][c];
    return v;
}

}  // namespace ma
