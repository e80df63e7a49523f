#include "fe/Assembly.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "core/Mpi.hpp"
#include "fe/ElasticityKernels.hpp"
#include "fe/ElementAssembler.hpp"

namespace ma {

namespace {

// Element stiffnesses with their equations, sorted (insertion sort of <= 24 entries), so that
// phase 2 merges each element row with the sorted matrix row.
class StiffnessKernel {
public:
    StiffnessKernel(const DirichletConstraints& c, CsrMatrix& matrix) : c_(c), matrix_(matrix) {}

    struct Part {                      // one worker's element matrices of the current batch
        std::vector<int> rows, local;  // per element: m (equation, local index), sorted
        std::vector<double> Ke;
        void clear() { rows.clear(), local.clear(), Ke.clear(); }
    };
    struct Entry {
        int nd = 0, m = 0;
        size_t Ke = 0, rows = 0;
    };

    Entry none(Part& part) const { return keep(part, nullptr, 0, nullptr); }

    template <class Ref, class Geometry>
    Entry classical(const Ref&, const Geometry& g, const ElementContext& el, Part& part) const {
        int edofs[Ref::dofs];
        double eK[Ref::dofs * Ref::dofs];
        classicalDofs<Ref>(el.mesh, el.numbering, el.cell, edofs);
        classicalStiffness(g, el.law, eK);
        return keep(part, edofs, Ref::dofs, eK);
    }

    Entry general(const ElementIntegration& ei, const PointGeometry& geo, const ElementContext& el, Part& part) const {
        ElementScratch& w = el.scratch;
        localDofs(el.mesh, el.numbering, ei, w.dofs);
        generalStiffness(ei, geo, el.law, el.dim, static_cast<int>(w.dofs.size()), w.values);
        return keep(part, w.dofs.data(), static_cast<int>(w.dofs.size()), w.values.data());
    }

    void scatter(const Part& p, const Entry& entry, int worker, int workers) const {
        const int* cols = matrix_.cols.data();
        double* values = matrix_.values.data();
        const int* rows = p.rows.data() + entry.rows;
        const int* local = p.local.data() + entry.rows;
        const double* eK = p.Ke.data() + entry.Ke;
        for (int i = 0; i < entry.m; ++i) {
            if (!ownedBy(rows[i], worker, workers)) continue;
            long long k = matrix_.rowStart[rows[i]];
            const double* Kr = eK + size_t(local[i]) * entry.nd;
            for (int j = 0; j < entry.m; ++j) {
                while (cols[k] < rows[j]) ++k;
                values[k] += Kr[local[j]];
            }
        }
    }

private:
    Entry keep(Part& part, const int* edofs, int nd, const double* eK) const {
        Entry entry;
        entry.nd = nd;
        entry.Ke = part.Ke.size(), entry.rows = part.rows.size();
        part.Ke.insert(part.Ke.end(), eK, eK + size_t(nd) * nd);
        int m = 0;
        for (int j = 0; j < nd; ++j) {
            const int row = c_.eq[edofs[j]];
            if (row < 0) continue;
            part.rows.push_back(row), part.local.push_back(j);
            for (size_t i = part.rows.size() - 1; i > entry.rows && part.rows[i - 1] > row; --i) {  // insertion sort
                std::swap(part.rows[i - 1], part.rows[i]);
                std::swap(part.local[i - 1], part.local[i]);
            }
            ++m;
        }
        entry.m = m;
        return entry;
    }

    const DirichletConstraints& c_;
    CsrMatrix& matrix_;
};

void addAdditionalTangent(const DirichletConstraints& c, const AdditionalTerms& additional,
                          const std::vector<double>& u, CsrMatrix& matrix) {
    additional.tangent(u, [&](int i, int j, double v) {
        const int row = c.eq[i], col = c.eq[j];
        if (row < 0 || col < 0) return;
        const long long k = matrix.find(row, col);
        if (k < 0) throw InternalError(fmt::format("additional term ({}, {}) outside the declared couplings", i, j));
        matrix.values[k] += v;
    });
}

// Multiplier scaling: the mean stiffness diagonal, so that the constraint rows are of the same
// magnitude as the stiffness rows. Distributed: the diagonal is the sum of the processes' parts,
// and rank 0 alone adds the multiplier blocks (MUMPS sums the processes' entries).
double addMultiplierBlocks(const DirichletConstraints& c, CsrMatrix& matrix, bool distributed) {
    std::vector<double> diagonal(size_t(c.freeCount), 0.0);
    for (int i = 0; i < c.freeCount; ++i) {
        const long long k = matrix.find(i, i);
        if (k >= 0) diagonal[size_t(i)] = matrix.values[k];
    }
    if (distributed) mpi::sum(diagonal);
    double sum = 0.0;
    for (double d : diagonal) sum += std::abs(d);
    const double alpha = c.freeCount > 0 && sum > 0.0 ? sum / c.freeCount : 1.0;
    if (distributed && !mpi::isRoot()) return alpha;
    for (size_t m = 0; m < c.multi.size(); ++m) {
        const int row = c.freeCount + int(m);
        for (const auto& [d, coef] : c.multi[m].terms) {
            matrix.values[matrix.find(row, c.eq[d])] += alpha * coef;
            matrix.values[matrix.find(c.eq[d], row)] += alpha * coef;
        }
    }
    return alpha;
}

size_t ownedCount(const Discretisation& space) {
    size_t n = 0;
    for (size_t e = 0; e < space.elementCount(); ++e) n += space.owns(e);
    return n;
}

}  // namespace

double assembleSystemMatrix(const Discretisation& space, const DirichletConstraints& c,
                            const AdditionalTerms* additional, const std::vector<double>& u, CsrMatrix& matrix) {
    const auto t0 = std::chrono::steady_clock::now();
    if (matrix.values.size() != matrix.cols.size()) matrix.values.assign(matrix.cols.size(), 0.0);
    else matrix.setZero();
    StiffnessKernel kernel(c, matrix);
    ElementAssembler assembler(space, kernel);
    double cpuTotal = 0.0;
    // This process's cells and contact points only when distributed (a failure on one process
    // stops all of them: core/Mpi.hpp).
    mpi::collectively([&] {
        cpuTotal = assembler.run();
        if (additional) addAdditionalTangent(c, *additional, u, matrix);
    });
    const double alpha = addMultiplierBlocks(c, matrix, space.distributed());
    msg().infof("    stiffness assembled: {} elements{}, {:.3f} s (cpu {:.3f} s, {:.3f} us per dof, {} thread(s)){}",
                space.elementCount(),
                space.distributed() ? fmt::format(" ({} on this process)", ownedCount(space)) : "", secondsSince(t0),
                cpuTotal, 1e6 * cpuTotal / std::max(1, space.numbering().size()), assembler.workers(),
                c.multi.empty() ? "" : fmt::format(", multiplier scaling {:.3e}", alpha));
    return alpha;
}

}  // namespace ma
