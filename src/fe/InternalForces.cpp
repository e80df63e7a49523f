#include "fe/InternalForces.hpp"

#include "core/Mpi.hpp"
#include "fe/ElasticityKernels.hpp"
#include "fe/ElementAssembler.hpp"
#include "fe/ResultFields.hpp"

namespace ma {

namespace {

// Element internal-force vectors with their dofs; phase 2 adds each into the blocks of 64 dofs
// the worker owns.
class InternalForceKernel {
public:
    InternalForceKernel(const Discretisation& space, const std::vector<double>& u, std::vector<double>& f,
                        const std::vector<char>* cells, PointWriter* points)
        : mesh_(space.mesh()), numbering_(space.numbering()), u_(u), f_(f), cells_(cells), points_(points) {}

    // Cells outside the chosen ones, and cells whose unknowns (those of their nodes) are all zero:
    // the forces are linear in them, so the element adds exactly nothing (the first residual of a
    // solve sets only the imposed values). Either way its geometry is not computed. Points written
    // for a field are written for every element.
    bool skips(int cell) const {
        if (cells_ && (*cells_)[size_t(cell)] == 0) return true;
        if (points_) return false;
        for (int node : mesh_.cellNodes(cell))
            for (int d = numbering_.first(node); d < numbering_.first(node + 1); ++d)
                if (u_[size_t(d)] != 0.0) return false;
        return true;
    }

    struct Part {  // one worker's element vectors of the current batch
        std::vector<int> dofs;
        std::vector<double> fe;
        void clear() { dofs.clear(), fe.clear(); }
    };
    struct Entry {
        int nd = 0;
        size_t offset = 0;
    };

    Entry none(Part& part) const { return keep(part, nullptr, nullptr, 0); }

    template <class Ref, class Geometry>
    Entry classical(const Ref& ref, const Geometry& g, const ElementContext& el, Part& part) const {
        int edofs[Ref::dofs];
        classicalDofs<Ref>(el.mesh, el.numbering, el.cell, edofs);
        double ue[Ref::dofs], fl[Ref::dofs] = {};
        for (int i = 0; i < Ref::dofs; ++i) ue[i] = u_[edofs[i]];
        classicalInternalForce(g, ue, el.law, fl, [&](int p, const double(*G)[3]) {
            if (points_) points_->classicalPoint(el.element, ref, g, p, G, el.law);
        });
        return keep(part, edofs, fl, Ref::dofs);
    }

    Entry general(const ElementIntegration& ei, const PointGeometry& geo, const ElementContext& el, Part& part) const {
        ElementScratch& w = el.scratch;
        localDofs(el.mesh, el.numbering, ei, w.dofs);
        if (points_) {
            const PointHook hook = [&](size_t p, const double(*G)[3]) {
                points_->generalPoint(el.element, ei, geo, p, G, el.law);
            };
            generalInternalForce(ei, geo, w.dofs, u_, el.law, el.dim, w.values, &hook);
        } else {
            generalInternalForce(ei, geo, w.dofs, u_, el.law, el.dim, w.values);
        }
        return keep(part, w.dofs.data(), w.values.data(), static_cast<int>(w.dofs.size()));
    }

    void scatter(const Part& part, const Entry& entry, int worker, int workers) const {
        const int* dofs = part.dofs.data() + entry.offset;
        const double* fe = part.fe.data() + entry.offset;
        for (int i = 0; i < entry.nd; ++i)
            if (ownedBy(dofs[i], worker, workers)) f_[dofs[i]] += fe[i];
    }

private:
    static Entry keep(Part& part, const int* dofs, const double* fe, int nd) {
        const Entry entry{nd, part.dofs.size()};
        part.dofs.insert(part.dofs.end(), dofs, dofs + nd);
        part.fe.insert(part.fe.end(), fe, fe + nd);
        return entry;
    }

    const Mesh& mesh_;
    const DofNumbering& numbering_;
    const std::vector<double>& u_;
    std::vector<double>& f_;
    const std::vector<char>* cells_;
    PointWriter* points_;
};

}  // namespace

void assembleInternalForces(const Discretisation& space, const std::vector<double>& u, std::vector<double>& f,
                            const std::vector<char>* cells, PointWriter* points) {
    f.assign(space.numbering().size(), 0.0);
    InternalForceKernel kernel(space, u, f, cells, points);
    mpi::collectively([&] { ElementAssembler(space, kernel).run(); });
    if (space.distributed()) mpi::sum(f);
}

}  // namespace ma
