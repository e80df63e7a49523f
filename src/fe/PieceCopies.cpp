#include "fe/PieceCopies.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>

#include "fe/NearNullSpace.hpp"

namespace ma {

namespace {

// The pieces of one node: value(j, k) is slot k in its piece j.
struct NodePieces {
    const ModelBlocks& blocks;
    int first, count;

    double value(int j, int k) const { return blocks.slotValue(first + j, k); }
};

// One entry of T: u_equation = sum value * v_unknown.
struct TEntry {
    int equation, unknown;
    double value;
};

struct Builder {
    Builder(const Discretisation& s, const DirichletConstraints& c, int r) : space(s), constraints(c), rows(r) {}

    const Discretisation& space;
    const DirichletConstraints& constraints;
    int rows;
    PieceBasis out;
    std::vector<TEntry> entries;  // T's entries, node after node
    std::vector<int> copyOf;      // per piece of the node: its copy or -1
    std::vector<int> free, kept;  // addComponent's slots and pieces (kept to reuse their memory)

    int equation(int node, int slot, int comp) const {
        const int d = space.numbering().dof(node, slot, comp);
        const int e = d < 0 ? -1 : constraints.eq[size_t(d)];
        return e >= 0 && e < rows ? e : -1;
    }

    int copyOfPiece(int j) {
        int& copy = copyOf[size_t(j)];
        if (copy < 0) copy = out.copies++;
        return copy;
    }

    // Component comp of node: u_F = M_R^-1 v_R, F its free slots, R the pieces whose value depends on
    // them. False when R and F do not match one to one.
    bool addComponent(int node, int comp, const NodePieces& psi, int slots) {
        free.clear(), kept.clear();
        for (int k = 0; k < slots; ++k)
            if (equation(node, k, comp) >= 0) free.push_back(k);
        if (free.empty()) return true;
        for (int j = 0; j < psi.count; ++j)
            for (int k : free)
                if (psi.value(j, k) != 0.0) {
                    kept.push_back(j);
                    break;
                }
        if (kept.size() != free.size()) return false;
        if (free.size() == 1) {  // a classical node's component: no matrix to invert
            const int copy = copyOfPiece(kept[0]);
            entries.push_back(
                {equation(node, free[0], comp), copy * out.blockSize + comp, 1.0 / psi.value(kept[0], free[0])});
            return true;
        }
        const Eigen::Index m = Eigen::Index(free.size());
        Eigen::MatrixXd M(m, m);
        for (Eigen::Index a = 0; a < m; ++a)
            for (Eigen::Index b = 0; b < m; ++b) M(a, b) = psi.value(kept[size_t(a)], free[size_t(b)]);
        const Eigen::FullPivLU<Eigen::MatrixXd> lu(M);
        if (!lu.isInvertible()) return false;
        const Eigen::MatrixXd inverse = lu.inverse();
        for (Eigen::Index a = 0; a < m; ++a) {
            const int e = equation(node, free[size_t(a)], comp);
            for (Eigen::Index b = 0; b < m; ++b) {
                const int copy = copyOfPiece(kept[size_t(b)]);
                if (inverse(a, b) != 0.0) entries.push_back({e, copy * out.blockSize + comp, inverse(a, b)});
            }
        }
        return true;
    }

    // The rigid modes on the copies of node (0 on the padding unknowns, set after), and their coordinates.
    void addModes(int node, int firstCopy) {
        const int dim = out.blockSize, modes = dim == 2 ? 3 : 6;
        const Vec3& x = space.mesh().coords[size_t(node)];
        for (int copy = firstCopy; copy < out.copies; ++copy) {
            for (int comp = 0; comp < dim; ++comp)
                for (int mode = 0; mode < modes; ++mode) out.modes.push_back(rigidModeValue(mode, comp, dim, x));
            for (int comp = 0; comp < dim; ++comp) out.coordinates.push_back(x[size_t(comp)]);
        }
    }
};

// T from its entries, row after row in the order they were found; the equation of the first empty
// row, or -1.
int assembleT(Builder& b) {
    const int n = b.out.size(), modes = b.out.blockSize == 2 ? 3 : 6;
    CsrMatrix& T = b.out.T;
    T.rows = b.rows;
    T.rowStart.assign(size_t(b.rows) + 1, 0);
    for (const TEntry& t : b.entries) ++T.rowStart[size_t(t.equation) + 1];
    for (size_t i = 0; i < size_t(b.rows); ++i) {
        if (T.rowStart[i + 1] == 0) return int(i);
        T.rowStart[i + 1] += T.rowStart[i];
    }
    T.cols.resize(b.entries.size()), T.values.resize(b.entries.size());
    std::vector<long long> next(T.rowStart.begin(), T.rowStart.end() - 1);
    b.out.padding.assign(size_t(n), 1);
    for (const TEntry& t : b.entries) {
        const size_t at = size_t(next[size_t(t.equation)]++);
        T.cols[at] = t.unknown, T.values[at] = t.value;
        b.out.padding[size_t(t.unknown)] = 0;
    }
    std::vector<TEntry>().swap(b.entries);
    // The modes were stored per unknown (modes values each): transpose to vector after vector, 0 on
    // the padding.
    std::vector<double> byVector(size_t(modes) * size_t(n), 0.0);
    for (size_t k = 0; k < size_t(n); ++k)
        if (!b.out.padding[k])
            for (size_t m = 0; m < size_t(modes); ++m) byVector[m * size_t(n) + k] = b.out.modes[k * size_t(modes) + m];
    b.out.modes = std::move(byVector);
    return -1;
}

}  // namespace

PieceBasis pieceBasisOf(const Discretisation& space, const DirichletConstraints& constraints, int rows) {
    PieceBasis none;
    if (constraints.freeCount != rows) {
        none.refusal = "the system has multiplier rows";
        return none;
    }
    const ModelBlocks blocks = findBlocks(space);
    const DofNumbering& numbering = space.numbering();
    Builder b(space, constraints, rows);
    b.out.blockSize = numbering.dim();
    b.out.blocks = blocks.count;
    b.entries.reserve(size_t(rows));
    for (int node = 0; node < numbering.nodeCount(); ++node) {
        const NodePieces psi{blocks, blocks.pieceOffsets[size_t(node)],
                             blocks.pieceOffsets[size_t(node) + 1] - blocks.pieceOffsets[size_t(node)]};
        if (psi.count == 0 || !numbering.hasNode(node)) continue;
        b.copyOf.assign(size_t(psi.count), -1);
        const int firstCopy = b.out.copies;
        for (int comp = 0; comp < numbering.dim(); ++comp)
            if (!b.addComponent(node, comp, psi, numbering.slots(node))) {
                none.refusal = fmt::format("the pieces of node {} do not determine its free slots",
                                           space.mesh().nodeNames[size_t(node)]);
                return none;
            }
        b.addModes(node, firstCopy);
    }
    const int empty = assembleT(b);
    if (empty < 0) return std::move(b.out);
    none.refusal =
        "some equations are not displacements of a node's pieces (crack-tip, contact or additional unknowns)";
    const auto dof = std::find(constraints.eq.begin(), constraints.eq.end(), empty);
    if (dof != constraints.eq.end()) {
        const int d = int(dof - constraints.eq.begin());
        none.refusal = fmt::format(
            "the unknown {} of node {} is not a displacement of a piece of its support "
            "(a crack-tip, contact or additional unknown)",
            numbering.componentOf(d), space.mesh().nodeNames[size_t(numbering.nodeOf(d))]);
    }
    return none;
}

}  // namespace ma
