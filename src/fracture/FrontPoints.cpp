#include "fracture/FrontPoints.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/Error.hpp"
#include "mesh/PointLocation.hpp"
#include "mesh/ShapeFunctions.hpp"
#include "xfem/CellGeometry.hpp"

namespace ma::fracture {

namespace {

bool containsPoint(const Mesh& mesh, int cell, const Vec3& x) {
    std::vector<Vec3> nodes;
    for (int n : mesh.cellNodes(cell)) nodes.push_back(mesh.coords[size_t(n)]);
    std::array<double, 3> xi{};
    const CellType type = mesh.cellTypes[size_t(cell)];
    if (!mapToReference(type, nodes, x, xi)) return false;
    const double tol = 1e-9;
    if (type == CellType::TETRA4)
        return xi[0] >= -tol && xi[1] >= -tol && xi[2] >= -tol && xi[0] + xi[1] + xi[2] <= 1 + tol;
    return std::abs(xi[0]) <= 1 + tol && std::abs(xi[1]) <= 1 + tol && std::abs(xi[2]) <= 1 + tol;
}

}  // namespace

double tipCellSize(const Mesh& mesh, const xfem::Crack& crack, const Vec3& x, const Vec3& direction) {
    double size = 0.0;
    for (int cell : crack.tipCells) {
        if (!containsPoint(mesh, cell, x)) continue;
        const auto nodes = mesh.cellNodes(cell);
        for (const auto& e : xfem::cellEdges(mesh.cellTypes[size_t(cell)])) {
            const Vec3 edge =
                difference(mesh.coords[size_t(nodes[size_t(e[1])])], mesh.coords[size_t(nodes[size_t(e[0])])]);
            size = std::max(size, std::abs(dot(edge, direction)));
        }
    }
    return size;
}

std::vector<FrontPoint> frontPoints3D(const Mesh& mesh, const xfem::Crack& crack, int numeFond) {
    if (numeFond < 1 || size_t(numeFond) > crack.fronts.size())
        throw UserError(
            fmt::format("NUME_FOND={}: crack {} has {} front(s)", numeFond, crack.name, crack.fronts.size()));
    const auto grln = xfem::nodalLevelSetGradient(mesh, crack.lsn);
    const auto grlt = xfem::nodalLevelSetGradient(mesh, crack.lst);
    const auto& front = crack.fronts[size_t(numeFond - 1)];
    std::vector<FrontPoint> out;
    for (size_t i = 0; i < front.points.size(); ++i) {
        FrontPoint p;
        p.point = front.points[i];
        p.abscissa = front.abscissa[i];
        const PointInCell at = locatePoint(mesh, p.point);
        if (at.cell < 0)
            throw UserError(
                fmt::format("point {} of front {} of crack {} lies in no cell", i + 1, numeFond, crack.name));
        const Vec3 n = interpolateAt(mesh, at, grln);
        Vec3 t = interpolateAt(mesh, at, grlt);
        const double nn = norm(n);
        if (!(nn > 0))
            throw UserError(fmt::format("the gradient of LSN of crack {} vanishes at point {} of front {}", crack.name,
                                        i + 1, numeFond));
        p.normal = scaled(n, 1.0 / nn);
        t = difference(t, scaled(p.normal, dot(t, p.normal)));
        const double tn = norm(t);
        if (!(tn > 0))
            throw UserError(fmt::format("the gradient of LST of crack {} vanishes at point {} of front {}", crack.name,
                                        i + 1, numeFond));
        p.direction = scaled(t, 1.0 / tn);
        p.cellSize = tipCellSize(mesh, crack, p.point, p.direction);
        out.push_back(p);
    }
    return out;
}

std::vector<FrontPoint> resampleFront(const std::vector<FrontPoint>& front, int count) {
    std::vector<FrontPoint> out;
    if (front.size() < 2 || count < 2) return front;
    const double total = front.back().abscissa;
    auto lerp = [](const Vec3& a, const Vec3& b, double w) {
        return Vec3{a[0] + w * (b[0] - a[0]), a[1] + w * (b[1] - a[1]), a[2] + w * (b[2] - a[2])};
    };
    for (int i = 0; i < count; ++i) {
        const double s = i * total / (count - 1);
        size_t k = 0;
        while (k + 2 < front.size() && front[k + 1].abscissa < s) ++k;
        const FrontPoint &a = front[k], &b = front[k + 1];
        const double span = b.abscissa - a.abscissa;
        const double w = span > 0 ? std::clamp((s - a.abscissa) / span, 0.0, 1.0) : 0.0;
        FrontPoint p;
        p.abscissa = s;
        p.point = lerp(a.point, b.point, w);
        p.normal = lerp(a.normal, b.normal, w);
        p.direction = lerp(a.direction, b.direction, w);
        p.cellSize = w < 0.5 ? a.cellSize : b.cellSize;
        out.push_back(p);
    }
    return out;
}

}  // namespace ma::fracture
