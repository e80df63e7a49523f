#include "mesh/LineOrdering.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include <fmt/format.h>

#include "core/Error.hpp"

namespace ma {

namespace {
const std::string& nodeName(const Mesh& mesh, int node) { return mesh.nodeNames[size_t(node)]; }

// The two end nodes of every cell (connectivity slots 0 and 1 of a SEG).
struct CellEnds {
    std::vector<int> first, second;
};

CellEnds segmentEnds(const Mesh& mesh, const std::vector<int>& cells) {
    CellEnds ends;
    CellType type{};
    for (size_t k = 0; k < cells.size(); ++k) {
        const CellType t = mesh.cellTypes[size_t(cells[k])];
        if (t != CellType::SEG2 && t != CellType::SEG3 && t != CellType::SEG4)
            throw UserError(fmt::format("OPTION='NOEUD_ORDO': cell {} is not a segment (SEG2, SEG3 or SEG4)",
                                        mesh.cellNames[size_t(cells[k])]));
        if (k > 0 && t != type)
            throw UserError(fmt::format("OPTION='NOEUD_ORDO': cell {} is not of the type of the first cell",
                                        mesh.cellNames[size_t(cells[k])]));
        type = t;
        auto nodes = mesh.cellNodes(cells[k]);
        ends.first.push_back(nodes[0]);
        ends.second.push_back(nodes[1]);
    }
    return ends;
}

// How many cell ends every node is; the line is one chain: at most two nodes end one cell only,
// none ends more than two.
std::vector<int> endCounts(const Mesh& mesh, const CellEnds& ends) {
    std::vector<int> count(size_t(mesh.nodeCount()), 0);
    for (size_t k = 0; k < ends.first.size(); ++k) ++count[size_t(ends.first[k])], ++count[size_t(ends.second[k])];
    int free = 0, branching = 0;
    for (int c : count) free += c == 1, branching += c > 2;
    if (free > 2 || branching > 0)
        throw UserError(
            "OPTION='NOEUD_ORDO': the cells do not form one line (a node ends more than two cells, "
            "or the line has more than two ends)");
    return count;
}

void checkEnd(const Mesh& mesh, const std::vector<int>& count, int node, bool sameEnds, const char* keyword) {
    if (count[size_t(node)] == 0)
        throw UserError(fmt::format("OPTION='NOEUD_ORDO': {} node {} is not an end of a cell of the line", keyword,
                                    nodeName(mesh, node)));
    if (!sameEnds && count[size_t(node)] != 1)
        throw UserError(
            fmt::format("OPTION='NOEUD_ORDO': {} node {} is not an end of the line", keyword, nodeName(mesh, node)));
}

// The origin code_aster picks when none is given: the first cell end (first nodes, then second
// nodes, cell by cell) that ends one cell only.
int defaultOrigin(const CellEnds& ends, const std::vector<int>& count, bool anyOrigin) {
    std::vector<int> all = ends.first;
    all.insert(all.end(), ends.second.begin(), ends.second.end());
    for (int n : all)
        if (count[size_t(n)] == 1) return n;
    if (!anyOrigin)
        throw UserError("OPTION='NOEUD_ORDO': the line is closed; give NOEUD_ORIG or GROUP_NO_ORIG, or ORIGINE='SANS'");
    return all.front();
}

// The nodes of a cell walked from `start`, the far end excluded.
void appendCell(const Mesh& mesh, int cell, int start, std::vector<int>& out) {
    auto nodes = mesh.cellNodes(cell);
    out.push_back(start);
    if (nodes.size() == 3) out.push_back(nodes[2]);
    if (nodes.size() == 4) {
        const bool forward = nodes[0] == start;
        out.push_back(forward ? nodes[2] : nodes[3]);
        out.push_back(forward ? nodes[3] : nodes[2]);
    }
}

// Reverses a closed line whose last step follows VECT_ORIE better than its first.
void orient(const Mesh& mesh, std::vector<int>& nodes, const Vec3& v) {
    if (!(dot(v, v) > 0)) return;
    if (nodes.size() < 3 || nodes.front() != nodes.back())
        throw UserError("OPTION='NOEUD_ORDO': VECT_ORIE orients a closed line only (origin = extremity)");
    auto cosine = [&](int from, int to) {
        const Vec3 d = difference(mesh.coords[size_t(to)], mesh.coords[size_t(from)]);
        return dot(d, v) / norm(d);
    };
    const size_t n = nodes.size();
    if (cosine(nodes[n - 1], nodes[n - 2]) > cosine(nodes[0], nodes[1])) std::reverse(nodes.begin(), nodes.end());
}
}  // namespace

std::vector<int> orderAlongSegment(const Mesh& mesh, std::vector<int> nodes, int origin, int extremity,
                                   double precision, bool relative) {
    const Vec3 a = mesh.coords[size_t(origin)], ab = difference(mesh.coords[size_t(extremity)], a);
    const double ab2 = dot(ab, ab);
    if (!(ab2 > 0)) throw UserError("OPTION='SEGM_DROI_ORDO': the origin and the extremity are the same point");
    std::vector<double> abscissa;
    for (int n : nodes) {
        const Vec3 am = difference(mesh.coords[size_t(n)], a);
        const double c = dot(am, ab) / ab2, am2 = dot(am, am);
        const Vec3 v{am[0] - c * ab[0], am[1] - c * ab[1], am[2] - c * ab[2]};
        const double off = std::sqrt(dot(v, v)), measure = relative ? off / std::sqrt(ab2) : off;
        if (measure > precision)
            throw UserError(
                fmt::format("OPTION='SEGM_DROI_ORDO': node {} is {:g} away from the segment (PRECISION {:g})",
                            nodeName(mesh, n), off, precision));
        if ((c < 0 || am2 > ab2) && (am2 - ab2) / ab2 > std::numeric_limits<double>::epsilon())
            throw UserError(fmt::format("OPTION='SEGM_DROI_ORDO': node {} lies outside the segment (abscissa {:g})",
                                        nodeName(mesh, n), c));
        abscissa.push_back(c);
    }
    std::vector<size_t> order(nodes.size());
    std::iota(order.begin(), order.end(), size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](size_t i, size_t j) { return abscissa[i] < abscissa[j]; });
    std::vector<int> sorted;
    for (size_t k = 0; k < order.size(); ++k) {
        if (k > 0 && abscissa[order[k]] == abscissa[order[k - 1]])
            throw UserError(fmt::format("OPTION='SEGM_DROI_ORDO': nodes {} and {} have the same abscissa",
                                        nodeName(mesh, nodes[order[k - 1]]), nodeName(mesh, nodes[order[k]])));
        sorted.push_back(nodes[order[k]]);
    }
    return sorted;
}

std::vector<int> nodesAlongLine(const Mesh& mesh, std::vector<int> cells, const LineEnds& ends) {
    if (cells.empty()) throw UserError("OPTION='NOEUD_ORDO': GROUP_MA holds no cell");
    const CellEnds cellEnds = segmentEnds(mesh, cells);
    const auto count = endCounts(mesh, cellEnds);
    const bool sameEnds = ends.origin >= 0 && ends.origin == ends.extremity;
    if (ends.extremity >= 0) checkEnd(mesh, count, ends.extremity, sameEnds, "the extremity");
    int junction = ends.origin;
    if (junction >= 0) checkEnd(mesh, count, junction, sameEnds, "the origin");
    else junction = defaultOrigin(cellEnds, count, ends.anyOrigin);

    // Walk the chain: the first remaining cell touching the current node comes next.
    std::vector<char> used(cells.size(), 0);
    std::vector<int> nodes;
    for (size_t step = 0; step < cells.size(); ++step) {
        size_t k = 0;
        while (k < cells.size() && (used[k] || (cellEnds.first[k] != junction && cellEnds.second[k] != junction))) ++k;
        if (k == cells.size())
            throw UserError(
                fmt::format("OPTION='NOEUD_ORDO': the cells do not form one connected line (it stops at "
                            "node {})",
                            nodeName(mesh, junction)));
        used[k] = 1;
        appendCell(mesh, cells[k], junction, nodes);
        junction = cellEnds.first[k] == junction ? cellEnds.second[k] : cellEnds.first[k];
    }
    nodes.push_back(junction);
    if (ends.extremity >= 0 && nodes.back() != ends.extremity)
        throw UserError(fmt::format("OPTION='NOEUD_ORDO': the line from the origin does not end at node {}",
                                    nodeName(mesh, ends.extremity)));
    orient(mesh, nodes, ends.orientation);
    return nodes;
}

}  // namespace ma
