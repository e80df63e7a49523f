#include "fe/Assembly.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numeric>
#include <stdexcept>

#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "core/Mpi.hpp"
#include "fe/ElasticityKernels.hpp"
#include "fe/ElementLoop.hpp"

namespace ma {

namespace {

// Element stiffnesses of one batch: phase 1, each worker keeps the matrices of its share (with
// their equations, sorted); phase 2, each worker adds the whole batch, in element order, into the
// rows it owns. Every matrix entry thus receives its element contributions in element order
// whatever the number of workers.
class StiffnessAssembler {
public:
    StiffnessAssembler(const Discretisation& space, const DirichletConstraints& c, CsrMatrix& matrix)
        : space_(space), c_(c), matrix_(matrix), workers_(elementWorkers(space.elementCount())), parts_(workers_),
          entries_(kElementBatch) {
        for (int t = 0; t < workers_; ++t) scratch_.emplace_back(space.material());
    }

    int workers() const { return workers_; }

    // Returns the workers' CPU time.
    double run() {
        std::vector<double> cpu;
        batchedElementLoop(
            space_.elementCount(), kElementBatch, workers_, cpu,
            [&](int t) { parts_[t].rows.clear(), parts_[t].local.clear(), parts_[t].Ke.clear(); },
            [&](size_t e, int t) { compute(e, t); }, [&](size_t, size_t count, int t) { scatter(count, t); });
        return std::accumulate(cpu.begin(), cpu.end(), 0.0);
    }

private:
    struct Part {  // one worker's element matrices of the current batch
        std::vector<int> rows, local;  // per element: m (equation, local index), sorted
        std::vector<double> Ke;
    };
    struct Entry {
        int part = 0, nd = 0, m = 0;
        size_t Ke = 0, rows = 0;
    };

    void compute(size_t e, int t) {
        const size_t slot = e % kElementBatch;
        if (!space_.owns(e)) return keep(t, slot, nullptr, 0, nullptr);  // another process's cell
        ElementScratch& w = scratch_[t];
        const Mesh& mesh = space_.mesh();
        const int cell = space_.model().elements[e].cell;
        const IsotropicLaw& law = w.laws.of(space_.model().elements[e]);
        space_.visit(
            e, w.general,
            [&](const auto& ref, const auto& g) {
                using Ref = std::decay_t<decltype(ref)>;
                int edofs[Ref::dofs];
                double eK[Ref::dofs * Ref::dofs];
                classicalDofs<Ref>(mesh, space_.numbering(), cell, edofs);
                classicalStiffness(g, law, eK);
                keep(t, slot, edofs, Ref::dofs, eK);
            },
            [&](const ElementIntegration& ei, const PointGeometry& geo) {
                localDofs(mesh, space_.numbering(), ei, w.dofs);
                generalStiffness(ei, geo, law, space_.dim(), static_cast<int>(w.dofs.size()), w.values);
                keep(t, slot, w.dofs.data(), static_cast<int>(w.dofs.size()), w.values.data());
            });
    }

    void keep(int t, size_t slot, const int* edofs, int nd, const double* eK) {
        Part& part = parts_[t];
        Entry& entry = entries_[slot];
        entry.part = t, entry.nd = nd;
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
    }

    void scatter(size_t count, int t) {
        const int* cols = matrix_.cols.data();
        double* values = matrix_.values.data();
        for (size_t slot = 0; slot < count; ++slot) {
            const Entry& entry = entries_[slot];
            const Part& p = parts_[entry.part];
            const int* rows = p.rows.data() + entry.rows;
            const int* local = p.local.data() + entry.rows;
            const double* eK = p.Ke.data() + entry.Ke;
            for (int i = 0; i < entry.m; ++i) {
                if (!ownedBy(rows[i], t, workers_)) continue;
                long long k = matrix_.rowStart[rows[i]];
                const double* Kr = eK + size_t(local[i]) * entry.nd;
                for (int j = 0; j < entry.m; ++j) {
                    while (cols[k] < rows[j]) ++k;
                    values[k] += Kr[local[j]];
                }
            }
        }
    }

    const Discretisation& space_;
    const DirichletConstraints& c_;
    CsrMatrix& matrix_;
    const int workers_;
    std::vector<Part> parts_;
    std::vector<Entry> entries_;
    std::vector<ElementScratch> scratch_;
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
    StiffnessAssembler assembler(space, c, matrix);
    double cpuTotal = 0.0;
    // This process's cells and contact points only when distributed (a failure on one process
    // stops all of them: core/Mpi.hpp).
    mpi::collectively([&] {
        cpuTotal = assembler.run();
        if (additional) addAdditionalTangent(c, *additional, u, matrix);
    });
    const double alpha = addMultiplierBlocks(c, matrix, space.distributed());
    msg().infof("    stiffness assembled: {} elements{}, {:.3f} s (cpu {:.3f} s, {:.3f} us per dof, {} thread(s)){}",
                space.elementCount(), space.distributed() ? fmt::format(" ({} on this process)", ownedCount(space)) : "",
                secondsSince(t0), cpuTotal, 1e6 * cpuTotal / std::max(1, space.numbering().size()), assembler.workers(),
                c.multi.empty() ? "" : fmt::format(", multiplier scaling {:.3e}", alpha));
    return alpha;
}

}  // namespace ma
