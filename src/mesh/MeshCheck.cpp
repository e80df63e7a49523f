#include "mesh/MeshCheck.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "core/Error.hpp"
#include "mesh/MeshMessages.hpp"

namespace ma {

namespace {

constexpr size_t kListed = 5;  // cells named in a message, the rest counted

std::string cellLabel(const Mesh& mesh, int c) {
    return mesh.cellNames[size_t(c)] + " (" + cellTypeName(mesh.cellTypes[size_t(c)]) + ")";
}

std::string listed(const std::vector<std::string>& items) {
    std::string s;
    for (size_t i = 0; i < items.size() && i < kListed; ++i) s += (i ? ", " : "") + items[i];
    return items.size() > kListed ? s + ", ..." : s;
}

// code_aster's MODELISA8_12 then MODELISA4_10: a node twice in one cell's connectivity stops the run.
void refuseRepeatedNodes(const Mesh& mesh, const std::string& path) {
    std::vector<std::string> found;
    for (int c = 0; c < mesh.cellCount(); ++c) {
        const auto n = mesh.cellNodes(c);
        for (size_t i = 1; i < n.size(); ++i)
            if (std::find(n.begin(), n.begin() + long(i), n[i]) != n.begin() + long(i)) {
                found.push_back(fmt::format("{}: {} twice", cellLabel(mesh, c), mesh.nodeNames[size_t(n[i])]));
                break;
            }
    }
    if (!found.empty())
        throw UserError(
            fmt::format("mesh {}: {} cell(s) have the same node twice in their connectivity "
                        "(topologically degenerate; code_aster stops on them too, MODELISA4_10): {}",
                        path, found.size(), listed(found)));
}

// The cell's nodes in increasing order (cells have at most 27).
std::span<const int> sortedNodes(const Mesh& mesh, int c, std::array<int, 27>& buffer) {
    const auto n = mesh.cellNodes(c);
    std::copy(n.begin(), n.end(), buffer.begin());
    std::sort(buffer.begin(), buffer.begin() + long(n.size()));
    return {buffer.data(), n.size()};
}

// Cells with the same set of nodes (code_aster compares the node sets of cells with as many nodes,
// whatever their order). Two such cells have the same lowest node: the cells are bucketed by it
// (a counting sort, linear) and compared within their bucket, which holds a few cells.
std::vector<std::pair<int, int>> doubleCells(const Mesh& mesh) {
    const int nc = mesh.cellCount();
    std::vector<int> lowest(static_cast<size_t>(nc)), start(size_t(mesh.nodeCount()) + 1, 0);
    for (int c = 0; c < nc; ++c) {
        const auto n = mesh.cellNodes(c);
        lowest[size_t(c)] = n.empty() ? 0 : *std::min_element(n.begin(), n.end());
        ++start[size_t(lowest[size_t(c)]) + 1];
    }
    for (size_t v = 1; v < start.size(); ++v) start[v] += start[v - 1];
    std::vector<int> bucketed(static_cast<size_t>(nc)), fill(start.begin(), start.end() - 1);
    for (int c = 0; c < nc; ++c) bucketed[size_t(fill[size_t(lowest[size_t(c)])]++)] = c;
    std::vector<std::pair<int, int>> pairs;
    std::array<int, 27> na{}, nb{};
    for (size_t v = 0; v + 1 < start.size(); ++v)
        for (int a = start[v]; a < start[v + 1]; ++a)
            for (int b = a + 1; b < start[v + 1]; ++b) {
                const int ca = bucketed[size_t(a)], cb = bucketed[size_t(b)];
                if (mesh.cellNodes(ca).size() != mesh.cellNodes(cb).size()) continue;
                const auto sa = sortedNodes(mesh, ca, na), sb = sortedNodes(mesh, cb, nb);
                if (std::equal(sa.begin(), sa.end(), sb.begin(), sb.end())) pairs.emplace_back(ca, cb);
            }
    std::sort(pairs.begin(), pairs.end(), [](const auto& p, const auto& q) { return p.second < q.second; });
    return pairs;
}

// Shortest over longest distance between two nodes of the cell (code_aster's MODELISA8_15 ratio).
// Squared lengths cannot overflow: checkCoordinates ran first.
double flatness(const Mesh& mesh, int c) {
    const auto n = mesh.cellNodes(c);
    double shortest = INFINITY, longest = 0.0;
    for (size_t a = 0; a < n.size(); ++a)
        for (size_t b = a + 1; b < n.size(); ++b) {
            const auto &p = mesh.coords[size_t(n[a])], &q = mesh.coords[size_t(n[b])];
            const double dx = p[0] - q[0], dy = p[1] - q[1], dz = p[2] - q[2];
            const double d2 = dx * dx + dy * dy + dz * dz;
            shortest = std::min(shortest, d2), longest = std::max(longest, d2);
        }
    return longest > 0.0 ? std::sqrt(shortest / longest) : 1.0;
}

}  // namespace

void checkCoordinates(const Mesh& mesh, const std::string& path) {
    std::array<double, 3> lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
    for (int n = 0; n < mesh.nodeCount(); ++n) {
        const auto& x = mesh.coords[size_t(n)];
        for (int j = 0; j < 3; ++j) {
            if (!std::isfinite(x[j]))
                throw UserError(fmt::format("mesh {}: node {} has a non-finite coordinate: ({}, {}, {})", path,
                                            mesh.nodeNames[size_t(n)], x[0], x[1], x[2]));
            if (std::abs(x[j]) > kCoordinateLimit)
                throw UserError(fmt::format(
                    "mesh {}: node {} has the coordinate {:g}, beyond {:g}: the finite elements form products of up to "
                    "three lengths (volumes, Jacobians) and of those with the moduli, which leave double precision "
                    "(1e308) at that scale; express the mesh in another length unit",
                    path, mesh.nodeNames[size_t(n)], x[j], kCoordinateLimit));
            lo[size_t(j)] = std::min(lo[size_t(j)], x[j]), hi[size_t(j)] = std::max(hi[size_t(j)], x[j]);
        }
    }
    double extent = 0.0;
    for (size_t j = 0; j < 3 && mesh.nodeCount() > 0; ++j) extent = std::max(extent, hi[j] - lo[j]);
    if (extent > 0.0 && extent < 1.0 / kCoordinateLimit)
        throw UserError(fmt::format(
            "mesh {}: the mesh measures {:g} (largest side of its bounding box), below {:g}: the products of up to "
            "three lengths the finite elements form (volumes, Jacobians) underflow double precision at that scale; "
            "express the mesh in another length unit",
            path, extent, 1.0 / kCoordinateLimit));
}

std::vector<FormattedMessage> veriMail(const Mesh& mesh, const std::string& path, double aplat) {
    refuseRepeatedNodes(mesh, path);
    std::vector<FormattedMessage> out;
    std::vector<char> used(size_t(mesh.nodeCount()), 0);
    for (int v : mesh.connectivity) used[size_t(v)] = 1;
    const auto orphans = std::count(used.begin(), used.end(), 0);
    if (orphans > 0) {
        int first = int(std::find(used.begin(), used.end(), 0) - used.begin());
        out.push_back(formatted(MODELISA_VERI_MAIL_ORPHAN_NODES, path, orphans, mesh.nodeNames[size_t(first)]));
    }
    std::vector<std::string> doubles;
    for (const auto& [a, b] : doubleCells(mesh))
        doubles.push_back(mesh.cellNames[size_t(a)] + " and " + cellLabel(mesh, b));
    if (!doubles.empty()) out.push_back(formatted(MODELISA8_13, path, doubles.size(), listed(doubles)));
    std::vector<std::string> flat;
    for (int c = 0; c < mesh.cellCount(); ++c)
        if (const double r = flatness(mesh, c); r < aplat)
            flat.push_back(fmt::format("{} ratio {:.3g}", cellLabel(mesh, c), r));
    if (!flat.empty()) out.push_back(formatted(MODELISA8_15, path, flat.size(), aplat, listed(flat)));
    return out;
}

}  // namespace ma
