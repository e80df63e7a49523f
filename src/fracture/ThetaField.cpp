#include "fracture/ThetaField.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "core/Error.hpp"
#include "mesh/PointLocation.hpp"
#include "mesh/ShapeFunctions.hpp"

namespace ma::fracture {

namespace {

std::vector<Vec3> cellCoords(const Mesh& mesh, int cell) {
    std::vector<Vec3> out;
    for (int n : mesh.cellNodes(cell)) out.push_back(mesh.coords[size_t(n)]);
    return out;
}

bool contains(const Mesh& mesh, int cell, const Vec3& x) {
    const auto nodes = cellCoords(mesh, cell);
    std::array<double, 3> xi{};
    if (!mapToReference(mesh.cellTypes[size_t(cell)], nodes, x, xi)) return false;
    const double tol = 1e-9;
    if (mesh.cellTypes[size_t(cell)] == CellType::TRIA3)
        return xi[0] >= -tol && xi[1] >= -tol && xi[0] + xi[1] <= 1 + tol;
    return std::abs(xi[0]) <= 1 + tol && std::abs(xi[1]) <= 1 + tol;
}

// code_aster's xtailm: the largest projection of an edge of the tip cells on the propagation
// direction.
double tipCellSize(const Mesh& mesh, const xfem::Crack& crack, const Vec3& x, const Vec3& e1) {
    double size = 0.0;
    for (int cell : crack.tipCells) {
        if (!contains(mesh, cell, x)) continue;
        const auto nodes = cellCoords(mesh, cell);
        for (size_t a = 0; a < nodes.size(); ++a)
            size = std::max(size, std::abs(dot(difference(nodes[(a + 1) % nodes.size()], nodes[a]), e1)));
    }
    return size;
}

}  // namespace

TipPoint tipPoint2D(const Mesh& mesh, const xfem::Crack& crack, const std::vector<Vec3>& grlt, int numeFond) {
    if (numeFond < 1 || size_t(numeFond) > crack.fronts.size() || crack.fronts[size_t(numeFond - 1)].points.empty())
        throw UserError(
            fmt::format("NUME_FOND={}: crack {} has {} front(s)", numeFond, crack.name, crack.fronts.size()));
    TipPoint tip;
    tip.point = crack.fronts[size_t(numeFond - 1)].points.front();
    const PointInCell at = locatePoint(mesh, tip.point);
    if (at.cell < 0) throw UserError(fmt::format("front {} of crack {} lies in no cell", numeFond, crack.name));
    Vec3 g{};
    std::vector<double> component(grlt.size());
    for (int c = 0; c < 2; ++c) {
        for (size_t n = 0; n < grlt.size(); ++n) component[n] = grlt[n][size_t(c)];
        g[size_t(c)] = interpolateAt(mesh, at, component);
    }
    const double length = norm(g);
    if (!(length > 0))
        throw UserError(fmt::format("the gradient of LST vanishes at front {} of crack {}", numeFond, crack.name));
    tip.frame.origin = tip.point;
    tip.frame.e1 = {g[0] / length, g[1] / length, 0.0};
    tip.frame.e2 = {-tip.frame.e1[1], tip.frame.e1[0], 0.0};
    tip.frame.e3 = {0.0, 0.0, 1.0};
    tip.cellSize = tipCellSize(mesh, crack, tip.point, tip.frame.e1);
    if (!(tip.cellSize > 0))
        throw InternalError(
            fmt::format("front {} of crack {}: no tip cell contains the front point", numeFond, crack.name));
    return tip;
}

std::vector<Vec3> thetaField2D(const Mesh& mesh, const Vec3& tip, const std::vector<Vec3>& grlt, double rInf,
                               double rSup) {
    const double eps = 1e-6;  // gcou2d's tolerance on the relative position in the crown
    std::vector<Vec3> theta(size_t(mesh.nodeCount()), Vec3{});
    for (size_t n = 0; n < theta.size(); ++n) {
        const Vec3& x = mesh.coords[n];
        const double alpha = (std::hypot(x[0] - tip[0], x[1] - tip[1]) - rInf) / (rSup - rInf);
        if (alpha >= 1 - eps) continue;
        const double g = std::hypot(grlt[n][0], grlt[n][1]);
        if (g <= 1e4 * std::numeric_limits<double>::epsilon())
            throw UserError(
                fmt::format("node {}: the gradient of LST (GRLTNO) vanishes inside R_SUP, so theta has "
                            "no direction there (code_aster's XFEM_12)",
                            mesh.nodeNames[n]));
        const double scale = alpha <= eps ? 1.0 : 1.0 - alpha;
        theta[n] = {scale * grlt[n][0] / g, scale * grlt[n][1] / g, 0.0};
    }
    return theta;
}

}  // namespace ma::fracture
