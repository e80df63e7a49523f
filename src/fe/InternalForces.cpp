#include "fe/InternalForces.hpp"

#include "core/Mpi.hpp"
#include "fe/ElasticityKernels.hpp"
#include "fe/ElementLoop.hpp"

namespace ma {

namespace {

class InternalForceAssembler {
public:
    InternalForceAssembler(const Discretisation& space, const std::vector<double>& u, std::vector<double>& f)
        : space_(space), u_(u), f_(f), workers_(elementWorkers(space.elementCount())), parts_(workers_),
          entries_(kElementBatch) {
        for (int t = 0; t < workers_; ++t) scratch_.emplace_back(space.material());
    }

    void run() {
        std::vector<double> cpu;
        batchedElementLoop(
            space_.elementCount(), kElementBatch, workers_, cpu,
            [&](int t) { parts_[t].dofs.clear(), parts_[t].fe.clear(); }, [&](size_t e, int t) { compute(e, t); },
            [&](size_t, size_t count, int t) { scatter(count, t); });
    }

private:
    struct Part {  // one worker's element vectors of the current batch
        std::vector<int> dofs;
        std::vector<double> fe;
    };
    struct Entry {
        int part = 0, nd = 0;
        size_t offset = 0;
    };

    void compute(size_t e, int t) {
        if (!space_.owns(e)) return keep(t, e, nullptr, nullptr, 0);  // another process's cell
        ElementScratch& w = scratch_[t];
        const Mesh& mesh = space_.mesh();
        const int cell = space_.model().elements[e].cell;
        const IsotropicLaw& law = w.laws.of(space_.model().elements[e]);
        space_.visit(
            e, w.general,
            [&](const auto& ref, const auto& g) {
                using Ref = std::decay_t<decltype(ref)>;
                int edofs[Ref::dofs];
                classicalDofs<Ref>(mesh, space_.numbering(), cell, edofs);
                double ue[Ref::dofs], fl[Ref::dofs] = {};
                for (int i = 0; i < Ref::dofs; ++i) ue[i] = u_[edofs[i]];
                classicalInternalForce(g, ue, law, fl);
                keep(t, e, edofs, fl, Ref::dofs);
            },
            [&](const ElementIntegration& ei, const PointGeometry& geo) {
                localDofs(mesh, space_.numbering(), ei, w.dofs);
                generalInternalForce(ei, geo, w.dofs, u_, law, space_.dim(), w.values);
                keep(t, e, w.dofs.data(), w.values.data(), static_cast<int>(w.dofs.size()));
            });
    }

    void keep(int t, size_t e, const int* dofs, const double* fe, int nd) {
        Part& part = parts_[t];
        entries_[e % kElementBatch] = {t, nd, part.dofs.size()};
        part.dofs.insert(part.dofs.end(), dofs, dofs + nd);
        part.fe.insert(part.fe.end(), fe, fe + nd);
    }

    void scatter(size_t count, int t) {
        for (size_t slot = 0; slot < count; ++slot) {
            const Entry& entry = entries_[slot];
            const int* dofs = parts_[entry.part].dofs.data() + entry.offset;
            const double* fe = parts_[entry.part].fe.data() + entry.offset;
            for (int i = 0; i < entry.nd; ++i)
                if (ownedBy(dofs[i], t, workers_)) f_[dofs[i]] += fe[i];
        }
    }

    const Discretisation& space_;
    const std::vector<double>& u_;
    std::vector<double>& f_;
    const int workers_;
    std::vector<Part> parts_;
    std::vector<Entry> entries_;
    std::vector<ElementScratch> scratch_;
};

}  // namespace

void assembleInternalForces(const Discretisation& space, const std::vector<double>& u, std::vector<double>& f) {
    f.assign(space.numbering().size(), 0.0);
    mpi::collectively([&] { InternalForceAssembler(space, u, f).run(); });
    if (space.distributed()) mpi::sum(f);
}

}  // namespace ma
