#include "mesh/GeometricSelection.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/Error.hpp"

namespace ma {

namespace {
// The node's position as the selection sees it: z dropped in a plane mesh.
Vec3 position(const Mesh& mesh, int node, int dim) {
    Vec3 x = mesh.coords[size_t(node)];
    if (dim == 2) x[2] = 0;
    return x;
}

Vec3 unitAxis(Vec3 v, const char* what) {
    const double n = norm(v);
    if (!(n > 0)) throw UserError(std::string(what) + ": the axis vector is zero");
    for (auto& c : v) c /= n;
    return v;
}

// Distance to the axis through `point` along the unit vector `axis`.
double axisDistance(const Vec3& x, const Vec3& point, const Vec3& axis) {
    const Vec3 d = difference(x, point);
    const double along = dot(d, axis);
    return std::sqrt(std::max(0.0, dot(d, d) - along * along));
}

bool keepCell(int inside, int total, CellCriterion criterion) {
    switch (criterion) {
        case CellCriterion::All: return inside == total;
        case CellCriterion::Majority: return inside >= (total + 1) / 2;
        case CellCriterion::AtLeastOne: return inside > 0;
    }
    return false;
}

void requireSpace(const Mesh& mesh, const char* option) {
    if (effectiveDimension(mesh) != 3)
        throw UserError(std::string(option) + " needs a 3D mesh (every node of this one has the same z)");
}
}  // namespace

std::vector<int> nodesOnSphere(const Mesh& mesh, Vec3 centre, double radius, double precision) {
    const int dim = effectiveDimension(mesh);
    if (dim == 2) centre[2] = 0;
    std::vector<int> out;
    for (int i = 0; i < mesh.nodeCount(); ++i)
        if (std::abs(distance(position(mesh, i, dim), centre) - radius) <= precision) out.push_back(i);
    return out;
}

std::vector<int> nodesOnCylinder(const Mesh& mesh, Vec3 point, Vec3 direction, double radius, double precision) {
    requireSpace(mesh, "OPTION='ENV_CYLINDRE'");
    const Vec3 axis = unitAxis(direction, "OPTION='ENV_CYLINDRE'");
    std::vector<int> out;
    for (int i = 0; i < mesh.nodeCount(); ++i)
        if (std::abs(axisDistance(mesh.coords[size_t(i)], point, axis) - radius) <= precision) out.push_back(i);
    return out;
}

CellCriterion cellCriterion(const std::string& critNoeud) {
    if (critNoeud == "TOUS") return CellCriterion::All;
    if (critNoeud == "MAJORITE") return CellCriterion::Majority;
    return CellCriterion::AtLeastOne;
}

std::vector<int> cellsInSphere(const Mesh& mesh, Vec3 centre, double radius, CellCriterion criterion) {
    const int dim = effectiveDimension(mesh);
    if (dim == 2) centre[2] = 0;
    std::vector<int> out;
    for (int c = 0; c < mesh.cellCount(); ++c) {
        auto nodes = mesh.cellNodes(c);
        int inside = 0;
        for (int v : nodes) inside += distance(position(mesh, v, dim), centre) <= radius;
        if (keepCell(inside, int(nodes.size()), criterion)) out.push_back(c);
    }
    return out;
}

std::vector<int> cellsInCylinder(const Mesh& mesh, Vec3 point, Vec3 direction, double radius, CellCriterion criterion) {
    requireSpace(mesh, "OPTION='CYLINDRE'");
    const Vec3 axis = unitAxis(direction, "OPTION='CYLINDRE'");
    std::vector<int> out;
    for (int c = 0; c < mesh.cellCount(); ++c) {
        auto nodes = mesh.cellNodes(c);
        int inside = 0;
        bool onPoint = false;
        for (int v : nodes) {
            const Vec3& x = mesh.coords[size_t(v)];
            onPoint = onPoint || x == point;
            inside += axisDistance(x, point, axis) <= radius;
        }
        if (onPoint || keepCell(inside, int(nodes.size()), criterion)) out.push_back(c);
    }
    return out;
}

Vec3 nauticalDirection(double alphaDeg, double betaDeg, int dimension) {
    const double a = alphaDeg * std::numbers::pi / 180.0, b = betaDeg * std::numbers::pi / 180.0;
    if (dimension == 2) return {std::cos(a), std::sin(a), 0.0};
    return {std::cos(a) * std::cos(b), std::sin(a) * std::cos(b), -std::sin(b)};
}

}  // namespace ma
