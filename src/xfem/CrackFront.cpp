#include "xfem/CrackFront.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <unordered_map>

#include "core/Error.hpp"
#include "mesh/ShapeFunctions.hpp"

namespace ma::xfem {

namespace {

// Faces of the 3D cells in local node numbers, each in cyclic order (a QUAD4 face interpolates as
// the cell restricted to it).
const std::vector<std::vector<int>>& cellFaces(CellType type) {
    static const std::vector<std::vector<int>> hexa{{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                                    {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
    static const std::vector<std::vector<int>> tetra{{0, 1, 2}, {0, 1, 3}, {1, 2, 3}, {0, 2, 3}};
    if (type == CellType::HEXA8) return hexa;
    if (type == CellType::TETRA4) return tetra;
    throw NotImplemented(
        fmt::format("crack front through a {} cell: miniaster finds it in TRIA3, QUAD4, TETRA4 and "
                    "HEXA8 cells",
                    cellTypeName(type)));
}

// Front points merged within a tolerance (a point on an edge or at a node is found on several
// faces): buckets of the tolerance's size, the 27 around a point searched.
class PointSet {
public:
    explicit PointSet(double tolerance) : tol_(tolerance) {}
    int add(const Vec3& p) {
        const auto key = keyOf(p);
        for (long dx = -1; dx <= 1; ++dx)
            for (long dy = -1; dy <= 1; ++dy)
                for (long dz = -1; dz <= 1; ++dz) {
                    auto it = buckets_.find(hash({key[0] + dx, key[1] + dy, key[2] + dz}));
                    if (it == buckets_.end()) continue;
                    for (int i : it->second)
                        if (distance(points[size_t(i)], p) <= tol_) return i;
                }
        points.push_back(p);
        buckets_[hash(key)].push_back(int(points.size()) - 1);
        return int(points.size()) - 1;
    }
    std::vector<Vec3> points;

private:
    std::array<long, 3> keyOf(const Vec3& p) const {
        return {long(std::floor(p[0] / tol_)), long(std::floor(p[1] / tol_)), long(std::floor(p[2] / tol_))};
    }
    static size_t hash(const std::array<long, 3>& k) {
        return size_t(k[0]) * 73856093u ^ size_t(k[1]) * 19349663u ^ size_t(k[2]) * 83492791u;
    }
    double tol_;
    std::unordered_map<size_t, std::vector<int>> buckets_;
};

double tipCellScale(const Mesh& mesh, const std::vector<int>& tipCells) {
    double sum = 0.0;
    for (int c : tipCells) {
        const auto nodes = mesh.cellNodes(c);
        sum += distance(mesh.coords[size_t(nodes[0])], mesh.coords[size_t(nodes[1])]);
    }
    return tipCells.empty() ? 1.0 : sum / double(tipCells.size());
}

// The points of one cell chained along the direction of their largest spread (one segment for the
// usual two points).
std::vector<std::pair<int, int>> cellSegments(std::vector<int> ids, const std::vector<Vec3>& points) {
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    std::vector<std::pair<int, int>> out;
    if (ids.size() < 2) return out;
    if (ids.size() > 2) {
        size_t a = 0, b = 1;
        for (size_t i = 0; i < ids.size(); ++i)
            for (size_t j = i + 1; j < ids.size(); ++j)
                if (distance(points[size_t(ids[i])], points[size_t(ids[j])]) >
                    distance(points[size_t(ids[a])], points[size_t(ids[b])]))
                    a = i, b = j;
        const Vec3 origin = points[size_t(ids[a])], dir = difference(points[size_t(ids[b])], origin);
        std::sort(ids.begin(), ids.end(), [&](int p, int q) {
            return dot(difference(points[size_t(p)], origin), dir) < dot(difference(points[size_t(q)], origin), dir);
        });
    }
    for (size_t i = 0; i + 1 < ids.size(); ++i) out.emplace_back(ids[i], ids[i + 1]);
    return out;
}

// Walks the segments from `start` while an unused segment continues the path.
std::vector<int> walk(int start, const std::vector<std::vector<std::pair<int, int>>>& adjacency,
                      std::vector<char>& used) {
    std::vector<int> path{start};
    for (int at = start;;) {
        int next = -1;
        for (const auto& [to, segment] : adjacency[size_t(at)])
            if (!used[size_t(segment)]) {
                used[size_t(segment)] = 1;
                next = to;
                break;
            }
        if (next < 0) return path;
        path.push_back(next);
        at = next;
    }
}

CrackFront frontOf(const std::vector<int>& path, const std::vector<Vec3>& points) {
    CrackFront f;
    f.closed = path.size() > 2 && path.front() == path.back();
    double s = 0.0;
    for (size_t i = 0; i < path.size(); ++i) {
        if (i > 0) s += distance(points[size_t(path[i - 1])], points[size_t(path[i])]);
        f.points.push_back(points[size_t(path[i])]);
        f.abscissa.push_back(s);
    }
    return f;
}

std::vector<CrackFront> chainFronts(const std::vector<std::pair<int, int>>& segments, const PointSet& set,
                                    const std::vector<int>& firstSeen) {
    std::vector<std::vector<std::pair<int, int>>> adjacency(set.points.size());
    for (size_t s = 0; s < segments.size(); ++s) {
        adjacency[size_t(segments[s].first)].emplace_back(segments[s].second, int(s));
        adjacency[size_t(segments[s].second)].emplace_back(segments[s].first, int(s));
    }
    std::vector<char> used(segments.size(), 0);
    std::vector<CrackFront> fronts;
    for (int p : firstSeen)  // open fronts, from their end met first
        if (adjacency[size_t(p)].size() == 1 && !used[size_t(adjacency[size_t(p)][0].second)])
            fronts.push_back(frontOf(walk(p, adjacency, used), set.points));
    for (int p : firstSeen)  // what is left is closed
        if (std::any_of(adjacency[size_t(p)].begin(), adjacency[size_t(p)].end(),
                        [&](const auto& e) { return !used[size_t(e.second)]; }))
            fronts.push_back(frontOf(walk(p, adjacency, used), set.points));
    return fronts;
}

template <class NodeList>
std::optional<Vec3> zeroOnNodes(const Mesh& mesh, CellType type, const NodeList& nodes, const std::vector<double>& lsn,
                                const std::vector<double>& lst) {
    std::array<Vec3, 4> x{};
    std::array<double, 4> n{}, t{};
    for (size_t a = 0; a < nodes.size(); ++a)
        x[a] = mesh.coords[size_t(nodes[a])], n[a] = lsn[size_t(nodes[a])], t[a] = lst[size_t(nodes[a])];
    const size_t count = nodes.size();
    return zeroOfTwoLevelSets(type, {x.data(), count}, {n.data(), count}, {t.data(), count});
}

}  // namespace

std::optional<Vec3> zeroOfTwoLevelSets(CellType type, std::span<const Vec3> vertices, std::span<const double> lsn,
                                       std::span<const double> lst) {
    const bool quad = type == CellType::QUAD4;
    std::array<double, 3> xi = quad ? std::array<double, 3>{0, 0, 0} : std::array<double, 3>{1.0 / 3, 1.0 / 3, 0};
    std::array<double, 4> N{};
    std::array<double, 12> dN{};
    bool converged = false;
    for (int it = 0; it < 60 && !converged; ++it) {
        shapeValues(type, xi, N);
        shapeDerivatives(type, xi, dN);
        double f[2] = {0, 0}, J[2][2] = {{0, 0}, {0, 0}};
        for (size_t a = 0; a < vertices.size(); ++a) {
            f[0] += N[a] * lsn[a], f[1] += N[a] * lst[a];
            for (int j = 0; j < 2; ++j)
                J[0][j] += dN[3 * a + size_t(j)] * lsn[a], J[1][j] += dN[3 * a + size_t(j)] * lst[a];
        }
        const double det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
        const double scale = (std::abs(J[0][0]) + std::abs(J[0][1])) * (std::abs(J[1][0]) + std::abs(J[1][1]));
        if (!(std::abs(det) > 1e-12 * scale)) return std::nullopt;  // level sets parallel on the cell
        const double d0 = -(J[1][1] * f[0] - J[0][1] * f[1]) / det, d1 = -(-J[1][0] * f[0] + J[0][0] * f[1]) / det;
        xi[0] += d0, xi[1] += d1;
        converged = std::abs(d0) + std::abs(d1) <= 1e-15 * (1.0 + std::abs(xi[0]) + std::abs(xi[1]));
        if (std::abs(xi[0]) > 10.0 || std::abs(xi[1]) > 10.0) return std::nullopt;
    }
    constexpr double tol = 1e-9;
    if (quad) {
        if (std::abs(xi[0]) > 1 + tol || std::abs(xi[1]) > 1 + tol) return std::nullopt;
        xi[0] = std::clamp(xi[0], -1.0, 1.0), xi[1] = std::clamp(xi[1], -1.0, 1.0);
    } else {
        if (xi[0] < -tol || xi[1] < -tol || xi[0] + xi[1] > 1 + tol) return std::nullopt;
        xi[0] = std::max(xi[0], 0.0), xi[1] = std::max(xi[1], 0.0);
        if (xi[0] + xi[1] > 1.0) {
            const double s = xi[0] + xi[1];
            xi[0] /= s, xi[1] /= s;
        }
    }
    return mapToPhysical(type, vertices, xi);
}

std::vector<CrackFront> crackFronts(const Mesh& mesh, const std::vector<double>& lsn, const std::vector<double>& lst,
                                    const std::vector<int>& tipCells) {
    PointSet set(1e-9 * tipCellScale(mesh, tipCells));
    std::vector<int> firstSeen;
    auto addPoint = [&](const Vec3& p) {
        const size_t before = set.points.size();
        const int id = set.add(p);
        if (set.points.size() > before) firstSeen.push_back(id);
        return id;
    };
    std::vector<CrackFront> fronts;
    if (mesh.maxCellDimension() == 2) {
        for (int c : tipCells) {
            const CellType type = mesh.cellTypes[size_t(c)];
            if (type != CellType::TRIA3 && type != CellType::QUAD4)
                throw NotImplemented(
                    fmt::format("crack front through a {} cell: miniaster finds it in TRIA3, "
                                "QUAD4, TETRA4 and HEXA8 cells",
                                cellTypeName(type)));
            if (auto p = zeroOnNodes(mesh, type, mesh.cellNodes(c), lsn, lst)) addPoint(*p);
        }
        for (const Vec3& p : set.points) fronts.push_back({{p}, {0.0}, false});
        return fronts;
    }
    std::map<std::vector<int>, std::optional<int>> faceCache;  // sorted face nodes -> point id
    std::vector<std::pair<int, int>> segments;
    for (int c : tipCells) {
        const auto nodes = mesh.cellNodes(c);
        std::vector<int> ids;
        for (const auto& face : cellFaces(mesh.cellTypes[size_t(c)])) {
            std::vector<int> faceNodes;
            for (int a : face) faceNodes.push_back(nodes[size_t(a)]);
            std::vector<int> key = faceNodes;
            std::sort(key.begin(), key.end());
            auto it = faceCache.find(key);
            if (it == faceCache.end()) {
                const CellType ft = face.size() == 4 ? CellType::QUAD4 : CellType::TRIA3;
                const auto p = zeroOnNodes(mesh, ft, faceNodes, lsn, lst);
                it = faceCache.emplace(key, p ? std::optional<int>(addPoint(*p)) : std::nullopt).first;
            }
            if (it->second) ids.push_back(*it->second);
        }
        for (const auto& s : cellSegments(ids, set.points))
            segments.emplace_back(std::min(s.first, s.second), std::max(s.first, s.second));
    }
    std::sort(segments.begin(), segments.end());
    segments.erase(std::unique(segments.begin(), segments.end()), segments.end());
    return chainFronts(segments, set, firstSeen);
}

}  // namespace ma::xfem
