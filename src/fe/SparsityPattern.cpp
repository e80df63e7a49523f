#include "fe/SparsityPattern.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <span>

#include "core/Messages.hpp"
#include "fe/ElementLoop.hpp"
#include "fe/Parallel.hpp"

namespace ma {

namespace {

// Builds the pattern in steps: node neighbours, row lengths, then columns. A node's rows are a
// contiguous range of equations; node ranges go to the workers.
class PatternBuilder {
public:
    PatternBuilder(const Discretisation& space, const DirichletConstraints& c, const AdditionalTerms* additional,
                   bool allElements)
        : space_(space),
          mesh_(space.mesh()),
          numbering_(space.numbering()),
          c_(c),
          nNodes_(mesh_.nodeCount()),
          workers_(workerCount()),
          allElements_(allElements) {
        collectMultipliers();
        collectExtraColumns(additional);
        nodeFree_.assign(nNodes_, 0);
        for (int node = 0; node < nNodes_; ++node)
            for (int d = numbering_.first(node); d < numbering_.first(node + 1); ++d) nodeFree_[node] += c_.eq[d] >= 0;
    }

    CsrMatrix build() {
        buildNeighbourGraphs();
        matrix_.rows = c_.equationCount();
        matrix_.rowStart.assign(matrix_.rows + 1, 0);
        countRows();
        for (int i = 0; i < matrix_.rows; ++i) matrix_.rowStart[i + 1] += matrix_.rowStart[i];
        matrix_.cols.resize(matrix_.rowStart.back());
        fillRows();
        return std::move(matrix_);
    }

private:
    struct Graph {  // neighbour nodes of one node range, per node: offsets into nodes
        std::vector<int> offsets{0}, nodes;
    };

    // Multipliers touching each dof.
    void collectMultipliers() {
        if (c_.multi.empty()) return;
        dofMultipliers_.resize(numbering_.size());
        for (size_t m = 0; m < c_.multi.size(); ++m)
            for (const auto& [d, coef] : c_.multi[m].terms) dofMultipliers_[d].push_back(c_.freeCount + int(m));
    }

    // Couplings of the additional terms, by dof (free dofs only, as equations).
    void collectExtraColumns(const AdditionalTerms* additional) {
        if (!additional) return;
        std::vector<std::pair<int, int>> pairs;
        additional->couplings(pairs);
        if (!pairs.empty()) extraColumns_.resize(c_.eq.size());
        for (const auto& [i, j] : pairs) {
            if (c_.eq[i] < 0 || c_.eq[j] < 0) continue;
            extraColumns_[i].push_back(c_.eq[j]);
            extraColumns_[j].push_back(c_.eq[i]);
        }
    }

    // Neighbour nodes of every node (itself included), sorted: one node range per worker, each
    // with its own list, so that the graph is the same for any number of workers.
    void buildNeighbourGraphs() {
        std::vector<int> start(nNodes_ + 1, 0);  // node -> elements incidence
        auto counted = [&](size_t e) { return allElements_ || space_.owns(e); };
        for (size_t e = 0; e < space_.elementCount(); ++e)
            if (counted(e))
                for (int node : mesh_.cellNodes(space_.model().elements[e].cell)) ++start[node + 1];
        for (int i = 0; i < nNodes_; ++i) start[i + 1] += start[i];
        std::vector<int> incidence(start.back()), fill(start.begin(), start.end() - 1);
        for (size_t e = 0; e < space_.elementCount(); ++e)
            if (counted(e))
                for (int node : mesh_.cellNodes(space_.model().elements[e].cell))
                    incidence[fill[node]++] = static_cast<int>(e);
        fill = {};
        graphs_.assign(workers_, Graph{});
        firstNode_.assign(workers_ + 1, nNodes_);
        parallelRanges(size_t(nNodes_), workers_, [&](size_t begin, size_t end, int t) {
            firstNode_[t] = int(begin);
            Graph& g = graphs_[t];
            g.offsets.reserve(end - begin + 1);
            g.nodes.reserve((start[end] - start[begin]) * 3);
            std::vector<int> marker(nNodes_, -1);  // other node -> last node that listed it
            std::vector<int> neighbours;
            for (size_t node = begin; node < end; ++node) {
                neighbours.clear();
                if (numbering_.hasNode(int(node))) {
                    for (int k = start[node]; k < start[node + 1]; ++k)
                        for (int other : mesh_.cellNodes(space_.model().elements[incidence[k]].cell))
                            if (marker[other] != int(node)) {
                                marker[other] = int(node);
                                neighbours.push_back(other);
                            }
                    std::sort(neighbours.begin(), neighbours.end());
                }
                g.nodes.insert(g.nodes.end(), neighbours.begin(), neighbours.end());
                g.offsets.push_back(static_cast<int>(g.nodes.size()));
            }
        });
    }

    std::span<const int> neighboursOf(int t, int node) const {
        const Graph& g = graphs_[t];
        const int i = node - firstNode_[t];
        return std::span<const int>(g.nodes.data() + g.offsets[i], size_t(g.offsets[i + 1] - g.offsets[i]));
    }

    bool special(int d) const { return !extraColumns_.empty() && !extraColumns_[d].empty(); }

    // Rare rows (contact couplings): element columns, couplings and multipliers, sorted, unique;
    // the diagonal too (a distributed pattern may hold no element of the row's node).
    void specialRow(int d, std::vector<int>& out, std::span<const int> neighbours) const {
        out.clear();
        out.push_back(c_.eq[d]);
        for (int other : neighbours)
            for (int e = numbering_.first(other); e < numbering_.first(other + 1); ++e)
                if (c_.eq[e] >= 0) out.push_back(c_.eq[e]);
        out.insert(out.end(), extraColumns_[d].begin(), extraColumns_[d].end());
        if (!dofMultipliers_.empty()) out.insert(out.end(), dofMultipliers_[d].begin(), dofMultipliers_[d].end());
        sortUnique(out);
    }

    // Rows of the additional terms' own unknowns: their declared couplings only.
    void ownRow(int d, std::vector<int>& out) const {
        out.clear();
        if (!extraColumns_.empty()) out = extraColumns_[d];
        out.push_back(c_.eq[d]);
        sortUnique(out);
    }

    static void sortUnique(std::vector<int>& out) {
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
    }

    // Row lengths into rowStart[row + 1].
    void countRows() {
        parallelRanges(size_t(nNodes_), workers_, [&](size_t begin, size_t end, int t) {
            std::vector<int> row;
            for (size_t node = begin; node < end; ++node) {
                const auto neighbours = neighboursOf(t, int(node));
                long long length = 0;
                for (int other : neighbours) length += nodeFree_[other];
                for (int d = numbering_.first(int(node)); d < numbering_.first(int(node) + 1); ++d) {
                    const int eq = c_.eq[d];
                    if (eq < 0) continue;
                    if (special(d)) {
                        specialRow(d, row, neighbours);
                        matrix_.rowStart[eq + 1] = static_cast<long long>(row.size());
                    } else {
                        matrix_.rowStart[eq + 1] =
                            length + (dofMultipliers_.empty() ? 0 : long(dofMultipliers_[d].size()));
                    }
                }
            }
        });
        std::vector<int> row;
        for (int d = numbering_.size(); d < int(c_.eq.size()); ++d)
            if (c_.eq[d] >= 0) {
                ownRow(d, row);
                matrix_.rowStart[c_.eq[d] + 1] = static_cast<long long>(row.size());
            }
        for (size_t m = 0; m < c_.multi.size(); ++m)
            matrix_.rowStart[c_.freeCount + int(m) + 1] = static_cast<long long>(c_.multi[m].terms.size());
    }

    void fillRows() {
        parallelRanges(size_t(nNodes_), workers_, [&](size_t begin, size_t end, int t) {
            std::vector<int> row;
            for (size_t node = begin; node < end; ++node) {
                const auto neighbours = neighboursOf(t, int(node));
                for (int d = numbering_.first(int(node)); d < numbering_.first(int(node) + 1); ++d) {
                    if (c_.eq[d] < 0) continue;
                    int* out = matrix_.cols.data() + matrix_.rowStart[c_.eq[d]];
                    if (special(d)) {
                        specialRow(d, row, neighbours);
                        std::copy(row.begin(), row.end(), out);
                        continue;
                    }
                    for (int other : neighbours)
                        for (int e = numbering_.first(other); e < numbering_.first(other + 1); ++e)
                            if (c_.eq[e] >= 0) *out++ = c_.eq[e];
                    // Multiplier equations come after every dof equation: the row stays sorted.
                    if (!dofMultipliers_.empty()) std::copy(dofMultipliers_[d].begin(), dofMultipliers_[d].end(), out);
                }
            }
        });
        std::vector<int> row;
        for (int d = numbering_.size(); d < int(c_.eq.size()); ++d)
            if (c_.eq[d] >= 0) {
                ownRow(d, row);
                std::copy(row.begin(), row.end(), matrix_.cols.begin() + matrix_.rowStart[c_.eq[d]]);
            }
        for (size_t m = 0; m < c_.multi.size(); ++m) {
            const int eq = c_.freeCount + int(m);
            auto out = matrix_.cols.begin() + matrix_.rowStart[eq];
            for (const auto& [d, coef] : c_.multi[m].terms) *out++ = c_.eq[d];
            std::sort(matrix_.cols.begin() + matrix_.rowStart[eq], matrix_.cols.begin() + matrix_.rowStart[eq + 1]);
        }
    }

    const Discretisation& space_;
    const Mesh& mesh_;
    const DofNumbering& numbering_;
    const DirichletConstraints& c_;
    const int nNodes_;
    const int workers_;
    const bool allElements_;
    std::vector<std::vector<int>> dofMultipliers_;
    std::vector<std::vector<int>> extraColumns_;
    std::vector<int> nodeFree_;  // free dofs (equations) of each node
    std::vector<Graph> graphs_;
    std::vector<int> firstNode_;
    CsrMatrix matrix_;
};

}  // namespace

CsrMatrix buildSparsityPattern(const Discretisation& space, const DirichletConstraints& c,
                               const AdditionalTerms* additional, bool allElements) {
    const auto t0 = std::chrono::steady_clock::now();
    const double cpu0 = threadCpuSeconds();
    CsrMatrix matrix = PatternBuilder(space, c, additional, allElements).build();
    msg().infof(
        "    matrix pattern{}: {} equations ({} free dofs, {} eliminated, {} multipliers), {} non-zeros, "
        "{:.3f} s (cpu {:.3f} s)",
        space.distributed() ? (allElements ? " of the whole matrix (ordering)" : " of this process's cells") : "",
        matrix.rows, c.freeCount, static_cast<int>(c.eq.size()) - c.freeCount, c.multi.size(), matrix.nonZeros(),
        secondsSince(t0), threadCpuSeconds() - cpu0);
    return matrix;
}

}  // namespace ma
