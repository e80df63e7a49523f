#include "fe/PieceCopies.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "fe/NearNullSpace.hpp"

namespace ma {

namespace {

// The slots' values in each piece of a node: row j = (1, psi of slots 1.. in piece j).
Eigen::MatrixXd pieceValues(const ModelBlocks& blocks, int node, int slots) {
    const int p0 = blocks.pieceOffsets[size_t(node)];
    const int pieces = blocks.pieceOffsets[size_t(node) + 1] - p0;
    Eigen::MatrixXd psi = Eigen::MatrixXd::Zero(pieces, slots);
    for (int j = 0; j < pieces; ++j) {
        psi(j, 0) = 1.0;
        const auto& values = blocks.piecePsi[size_t(p0 + j)];
        for (int k = 1; k < slots && size_t(k - 1) < values.size(); ++k) psi(j, k) = values[size_t(k - 1)];
    }
    return psi;
}

struct Builder {
    Builder(const Discretisation& s, const DirichletConstraints& c, int r)
        : space(s), constraints(c), rows(r), tRows(size_t(r)) {}

    const Discretisation& space;
    const DirichletConstraints& constraints;
    int rows;
    PieceBasis out;
    std::vector<std::vector<std::pair<int, double>>> tRows;  // per equation: (v unknown, T_ik)
    std::vector<int> copyOf;                                 // per piece of the node: its copy or -1

    int equation(int node, int slot, int comp) const {
        const int d = space.numbering().dof(node, slot, comp);
        const int e = d < 0 ? -1 : constraints.eq[size_t(d)];
        return e >= 0 && e < rows ? e : -1;
    }

    // Component comp of node: u_F = M_R^-1 v_R, F its free slots, R the pieces whose value depends on
    // them. False when R and F do not match one to one.
    bool addComponent(int node, int comp, const Eigen::MatrixXd& psi) {
        const int dim = out.blockSize;
        std::vector<int> free, kept;
        for (int k = 0; k < psi.cols(); ++k)
            if (equation(node, k, comp) >= 0) free.push_back(k);
        if (free.empty()) return true;
        for (int j = 0; j < psi.rows(); ++j)
            for (int k : free)
                if (psi(j, k) != 0.0) {
                    kept.push_back(j);
                    break;
                }
        if (kept.size() != free.size()) return false;
        const Eigen::Index m = Eigen::Index(free.size());
        Eigen::MatrixXd M(m, m);
        for (Eigen::Index a = 0; a < m; ++a)
            for (Eigen::Index b = 0; b < m; ++b) M(a, b) = psi(kept[size_t(a)], free[size_t(b)]);
        const Eigen::FullPivLU<Eigen::MatrixXd> lu(M);
        if (!lu.isInvertible()) return false;
        const Eigen::MatrixXd inverse = lu.inverse();
        for (Eigen::Index a = 0; a < m; ++a) {
            auto& row = tRows[size_t(equation(node, free[size_t(a)], comp))];
            for (Eigen::Index b = 0; b < m; ++b) {
                int& copy = copyOf[size_t(kept[size_t(b)])];
                if (copy < 0) copy = out.copies++;
                if (inverse(a, b) != 0.0) row.emplace_back(copy * dim + comp, inverse(a, b));
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

void assembleT(Builder& b) {
    const int n = b.out.size(), modes = b.out.blockSize == 2 ? 3 : 6;
    CsrMatrix& T = b.out.T;
    T.rows = b.rows;
    T.rowStart.assign(1, 0);
    b.out.padding.assign(size_t(n), 1);
    for (auto& row : b.tRows) {
        for (const auto& [k, value] : row) {
            T.cols.push_back(k);
            T.values.push_back(value);
            b.out.padding[size_t(k)] = 0;
        }
        T.rowStart.push_back(static_cast<long long>(T.cols.size()));
    }
    // The modes were stored per unknown (modes values each): transpose to vector after vector, 0 on
    // the padding.
    std::vector<double> byVector(size_t(modes) * size_t(n), 0.0);
    for (size_t k = 0; k < size_t(n); ++k)
        if (!b.out.padding[k])
            for (size_t m = 0; m < size_t(modes); ++m) byVector[m * size_t(n) + k] = b.out.modes[k * size_t(modes) + m];
    b.out.modes = std::move(byVector);
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
    for (int node = 0; node < numbering.nodeCount(); ++node) {
        const int p0 = blocks.pieceOffsets[size_t(node)];
        const int pieces = blocks.pieceOffsets[size_t(node) + 1] - p0;
        if (pieces == 0 || !numbering.hasNode(node)) continue;
        const Eigen::MatrixXd psi = pieceValues(blocks, node, numbering.slots(node));
        b.copyOf.assign(size_t(pieces), -1);
        const int firstCopy = b.out.copies;
        for (int comp = 0; comp < numbering.dim(); ++comp)
            if (!b.addComponent(node, comp, psi)) {
                none.refusal = fmt::format("the pieces of node {} do not determine its free slots",
                                           space.mesh().nodeNames[size_t(node)]);
                return none;
            }
        b.addModes(node, firstCopy);
    }
    for (int i = 0; i < rows; ++i)
        if (b.tRows[size_t(i)].empty()) {
            none.refusal =
                "some equations are not displacements of a node's pieces (crack-tip, contact or "
                "additional unknowns)";
            const auto dof = std::find(constraints.eq.begin(), constraints.eq.end(), i);
            if (dof != constraints.eq.end()) {
                const int d = int(dof - constraints.eq.begin());
                none.refusal = fmt::format(
                    "the unknown {} of node {} is not a displacement of a piece of its support "
                    "(a crack-tip, contact or additional unknown)",
                    numbering.componentOf(d), space.mesh().nodeNames[size_t(numbering.nodeOf(d))]);
            }
            return none;
        }
    assembleT(b);
    return std::move(b.out);
}

}  // namespace ma
