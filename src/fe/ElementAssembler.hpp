#pragma once
// The threaded assembly of element quantities (stiffness matrices, internal-force vectors) into
// global arrays, written once: elements go in batches (batchedElementLoop); phase 1, each worker
// computes the element results of its share of the batch into its own part; phase 2, each worker
// adds the whole batch, in element order, into the entries it owns. Every global entry thus
// receives its contributions in element order whatever the number of workers: the same bits as a
// serial loop. Elements of another process (distributed runs, docs/mpi.md) contribute nothing.
#include <numeric>
#include <vector>

#include "fe/Discretisation.hpp"
#include "fe/ElasticityKernels.hpp"
#include "fe/ElementLoop.hpp"

namespace ma {

// What a kernel sees of the element it computes.
struct ElementContext {
    size_t element;  // index in the model's elements
    const Mesh& mesh;
    const DofNumbering& numbering;
    int cell;
    int dim;
    const IsotropicLaw& law;
    ElementScratch& scratch;  // the worker's buffers of the general path
};

// Kernel: what is computed per element and where it goes.
//   struct Part   { void clear(); ... }  one worker's element results of the current batch
//   struct Entry  { ... }                where one element's result lies in its worker's Part
//   Entry none(Part&)                                       an element this process does not own
//   Entry classical(const Ref&, const Geometry&, const ElementContext&, Part&)   fixed sizes
//   Entry general(const ElementIntegration&, const PointGeometry&, const ElementContext&, Part&)
//   void scatter(const Part&, const Entry&, int worker, int workers)   adds the owned entries
// and optionally
//   bool skips(int cell) const        true: the element adds nothing (decided before its geometry)
template <class Kernel>
class ElementAssembler {
public:
    ElementAssembler(const Discretisation& space, Kernel& kernel)
        : space_(space),
          kernel_(kernel),
          workers_(elementWorkers(space.elementCount())),
          parts_(workers_),
          slots_(kElementBatch) {
        for (int t = 0; t < workers_; ++t) scratch_.emplace_back(space.material());
    }

    int workers() const { return workers_; }

    // Returns the workers' CPU time.
    double run() {
        std::vector<double> cpu;
        batchedElementLoop(
            space_.elementCount(), kElementBatch, workers_, cpu, [&](int t) { parts_[t].clear(); },
            [&](size_t e, int t) { compute(e, t); }, [&](size_t, size_t count, int t) { scatter(count, t); });
        return std::accumulate(cpu.begin(), cpu.end(), 0.0);
    }

private:
    struct Slot {  // one element of the current batch
        int part = 0;
        typename Kernel::Entry entry;
    };

    void compute(size_t e, int t) {
        Slot& slot = slots_[e % kElementBatch];
        slot.part = t;
        typename Kernel::Part& part = parts_[t];
        const ModelElement& element = space_.model().elements[e];
        if (!space_.owns(e) || skips(element.cell)) {
            slot.entry = kernel_.none(part);
            return;
        }
        ElementScratch& w = scratch_[t];
        const ElementContext context{
            e, space_.mesh(), space_.numbering(), element.cell, space_.dim(), w.laws.of(element), w};
        space_.visit(
            e, w.general,
            [&](const auto& ref, const auto& g) { slot.entry = kernel_.classical(ref, g, context, part); },
            [&](const ElementIntegration& ei, const PointGeometry& geo) {
                slot.entry = kernel_.general(ei, geo, context, part);
            });
    }

    bool skips(int cell) const {
        if constexpr (requires { kernel_.skips(cell); }) return kernel_.skips(cell);
        return false;
    }

    void scatter(size_t count, int t) {
        for (size_t s = 0; s < count; ++s) kernel_.scatter(parts_[slots_[s].part], slots_[s].entry, t, workers_);
    }

    const Discretisation& space_;
    Kernel& kernel_;
    const int workers_;
    std::vector<typename Kernel::Part> parts_;
    std::vector<Slot> slots_;
    std::vector<ElementScratch> scratch_;
};

}  // namespace ma
