#pragma once
// The discrete space of a mechanical problem: the model's elements, the material of each, the
// unknowns (DofNumbering), the X-FEM description of every enriched element (computed once) and
// which dofs some element really uses. Built once per problem; every assembly, force and field
// loop reads it.
#include <functional>
#include <memory>
#include <vector>

#include "fe/DofNumbering.hpp"
#include "fe/ElementIntegration.hpp"
#include "fe/ElementLoop.hpp"
#include "fe/Material.hpp"
#include "fe/Model.hpp"

namespace ma {

class Discretisation {
public:
    // Checks every element's material (IsotropicLaw::from) and marks the dofs elements use.
    // With `describe`, only the enriched cells it accepts get their X-FEM description (CALC_G reads
    // the cells around a tip of a model whose crack-tip elements hold ~10^5 points); integrationOf
    // and pointCount on another enriched element are an InternalError.
    Discretisation(std::shared_ptr<const Model> model, std::shared_ptr<const MaterialField> material,
                   const ExtraUnknowns& extra, const std::function<bool(int cell)>& describe = {});

    const Model& model() const { return *model_; }
    const Mesh& mesh() const { return *model_->mesh; }
    const MaterialField& material() const { return *material_; }
    const DofNumbering& numbering() const { return numbering_; }
    int dim() const { return numbering_.dim(); }
    size_t elementCount() const { return model_->elements.size(); }

    bool isEnriched(size_t e) const { return !enrichedIndex_.empty() && enrichedIndex_[e] != -1; }
    // The X-FEM description of element e when it is enriched, else its classical one (in scratch).
    // A crack-tip element's is handed out in scratch, its points shared with the stored description
    // (not copied) and its tip fields computed again (not kept).
    const ElementIntegration& integrationOf(size_t e, ElementIntegration& scratch) const;
    // Integration points of element e.
    size_t pointCount(size_t e) const;
    // True when some element uses dof d (psi not zero at one of its points at least).
    bool attached(int d) const { return attached_[d] != 0; }

    // Cells dealt to the processes (docs/mpi.md): each process computes only the elements it owns.
    // Without it (one process, or a solver that is not distributed), every element is owned.
    // Collective: every process calls it (rank 0 partitions, the others receive its partition).
    void distribute(int processes, int rank);
    bool distributed() const { return !owner_.empty(); }
    int ownerOf(size_t e) const { return owner_.empty() ? rank_ : owner_[e]; }
    bool owns(size_t e) const { return ownerOf(e) == rank_; }
    // The same for a cell of the mesh (a model's cell; false for any other when distributed).
    bool ownsCell(int cell) const;
    // Elements per process (empty when not distributed).
    std::vector<int> elementsPerProcess() const;

    // Element e on its fastest path (visitVolumeElement): onClassical(ref, g) or onGeneral(ei, geo).
    template <class OnClassical, class OnGeneral>
    void visit(size_t e, GeneralElementScratch& scratch, OnClassical&& onClassical, OnGeneral&& onGeneral) const {
        visitVolumeElement(
            mesh(), dim(), model_->elements[e].cell, isEnriched(e), scratch,
            [&](ElementIntegration& s) -> const ElementIntegration& { return integrationOf(e, s); }, onClassical,
            onGeneral);
    }

private:
    void markAttached(const ElementIntegration& ei, std::vector<int>& dofs);

    std::shared_ptr<const Model> model_;
    std::shared_ptr<const MaterialField> material_;
    DofNumbering numbering_;
    std::vector<ElementIntegration> enrichedIntegrations_;  // X-FEM elements only, without tip fields
    std::vector<TipLaw> tipLaws_;                           // per enrichedIntegrations_ (crack tips)
    // element -> index in enrichedIntegrations_, -1 (empty: no X-FEM), kNotDescribed
    std::vector<int> enrichedIndex_;
    static constexpr int kNotDescribed = -2;
    std::vector<char> attached_;    // per dof: used by some element
    std::vector<int> owner_;        // element -> process (empty: not distributed)
    std::vector<int> cellElement_;  // mesh cell -> element (when distributed)
    int rank_ = 0, processes_ = 1;
};

}  // namespace ma
