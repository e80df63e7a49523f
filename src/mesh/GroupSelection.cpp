#include "mesh/GroupSelection.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_set>

#include "core/Error.hpp"

namespace ma {

namespace {
Vec3 nonZeroUnit(Vec3 v, const char* what) {
    const double n = norm(v);
    if (!(n > 0)) throw UserError(std::string(what) + ": the normal vector is zero");
    for (auto& x : v) x /= n;
    return v;
}

// Distance of every node to the plane (point, unit normal), vectorised over nodes.
std::vector<char> nearPlane(const Mesh& mesh, const Vec3& point, const Vec3& n, double tol) {
    std::vector<char> near(mesh.coords.size());
    for (size_t i = 0; i < mesh.coords.size(); ++i) {
        const auto& x = mesh.coords[i];
        const double d = (x[0] - point[0]) * n[0] + (x[1] - point[1]) * n[1] + (x[2] - point[2]) * n[2];
        near[i] = std::abs(d) <= tol;
    }
    return near;
}
}  // namespace

std::vector<int> nodesOfCells(const Mesh& mesh, const std::vector<int>& cells, NodeCriterion crit) {
    std::vector<char> mark(size_t(mesh.nodeCount()), 0);
    for (int c : cells) {
        const CellType t = mesh.cellTypes[size_t(c)];
        auto nodes = mesh.cellNodes(c);
        const int nv = vertexCount(t), nc = centreNodeCount(t), n = int(nodes.size());
        for (int k = 0; k < n; ++k) {
            const bool vertex = k < nv, centre = k >= n - nc, mid = !vertex && !centre;
            if (crit == NodeCriterion::All || (crit == NodeCriterion::Vertices && vertex) ||
                (crit == NodeCriterion::MidNodes && mid) || (crit == NodeCriterion::Centres && centre))
                mark[size_t(nodes[size_t(k)])] = 1;
        }
    }
    std::vector<int> out;
    for (int i = 0; i < mesh.nodeCount(); ++i)
        if (mark[size_t(i)]) out.push_back(i);
    return out;
}

std::vector<int> nodesOnPlane(const Mesh& mesh, Vec3 point, Vec3 normal, double precision) {
    if (effectiveDimension(mesh) == 2) normal[2] = 0, point[2] = mesh.coords.empty() ? 0 : mesh.coords[0][2];
    const Vec3 n = nonZeroUnit(normal, "OPTION='PLAN'");
    auto near = nearPlane(mesh, point, n, precision);
    std::vector<int> out;
    for (int i = 0; i < mesh.nodeCount(); ++i)
        if (near[size_t(i)]) out.push_back(i);
    return out;
}

std::vector<int> cellsWithNormal(const Mesh& mesh, Vec3 direction, double anglePrecisionDeg, bool checkSign) {
    const int dim = effectiveDimension(mesh);
    if (dim == 2) direction[2] = 0;
    const Vec3 v = nonZeroUnit(direction, "OPTION='FACE_NORMALE'");
    const double tol = anglePrecisionDeg * std::numbers::pi / 180.0;
    std::vector<int> out;
    for (int c = 0; c < mesh.cellCount(); ++c) {
        if (cellDimension(mesh.cellTypes[size_t(c)]) != dim - 1) continue;
        Vec3 n = cellNormal(mesh, c);
        const double len = norm(n);
        if (!(len > 0)) continue;  // degenerate cell: no normal
        const double cosine = dot(n, v) / len;
        if (checkSign && cosine <= 0) continue;
        if (std::acos(std::min(1.0, std::abs(cosine))) < tol) out.push_back(c);
    }
    return out;
}

std::vector<int> cellsInBand(const Mesh& mesh, Vec3 point, Vec3 normal, double dist, const std::string& criterion) {
    if (effectiveDimension(mesh) == 2) normal[2] = 0, point[2] = mesh.coords.empty() ? 0 : mesh.coords[0][2];
    const Vec3 n = nonZeroUnit(normal, "OPTION='BANDE'");
    auto near = nearPlane(mesh, point, n, dist);
    std::vector<int> out;
    for (int c = 0; c < mesh.cellCount(); ++c) {
        auto nodes = mesh.cellNodes(c);
        int inside = 0;
        for (int v : nodes) inside += near[size_t(v)];
        const int total = int(nodes.size());
        const bool keep = criterion == "TOUS"       ? inside == total
                          : criterion == "MAJORITE" ? 2 * inside >= total
                                                    : inside > 0;
        if (keep) out.push_back(c);
    }
    return out;
}

std::vector<int> filterCellType(const Mesh& mesh, const std::vector<int>& cells, const std::string& typeFilter) {
    if (typeFilter.empty() || typeFilter == "TOUT") return cells;
    std::vector<int> out;
    if (typeFilter.size() == 2 && typeFilter[1] == 'D') {
        const int dim = typeFilter[0] - '0';
        for (int c : cells)
            if (cellDimension(mesh.cellTypes[size_t(c)]) == dim) out.push_back(c);
        return out;
    }
    CellType t;
    if (!cellTypeFromName(typeFilter, t)) throw UserError("TYPE_MAILLE='" + typeFilter + "' is not a cell type");
    for (int c : cells)
        if (mesh.cellTypes[size_t(c)] == t) out.push_back(c);
    return out;
}

std::vector<int> intersectionOf(const std::vector<const std::vector<int>*>& lists) {
    if (lists.empty()) return {};
    std::vector<int> out = *lists.front();
    for (size_t k = 1; k < lists.size(); ++k) {
        std::unordered_set<int> other(lists[k]->begin(), lists[k]->end());
        out.erase(std::remove_if(out.begin(), out.end(), [&](int e) { return !other.count(e); }), out.end());
    }
    return out;
}

std::vector<int> unionOf(const std::vector<const std::vector<int>*>& lists) {
    std::vector<int> out;
    std::unordered_set<int> seen;
    for (const auto* l : lists)
        for (int e : *l)
            if (seen.insert(e).second) out.push_back(e);
    return out;
}

std::vector<int> differenceOf(const std::vector<const std::vector<int>*>& lists) {
    if (lists.empty()) return {};
    std::unordered_set<int> removed;
    for (size_t k = 1; k < lists.size(); ++k) removed.insert(lists[k]->begin(), lists[k]->end());
    std::vector<int> out;
    for (int e : *lists.front())
        if (!removed.count(e)) out.push_back(e);
    return out;
}

}  // namespace ma
