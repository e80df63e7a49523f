#include "fe/Discretisation.hpp"

#include <string>

#include "core/Error.hpp"
#include "core/Mpi.hpp"
#include "fe/ElasticityKernels.hpp"
#include "fe/Enrichment.hpp"
#include "fe/Quadrature.hpp"
#include "mesh/CellPartition.hpp"

namespace ma {

Discretisation::Discretisation(std::shared_ptr<const Model> model, std::shared_ptr<const MaterialField> material,
                               const ExtraUnknowns& extra, const std::function<bool(int cell)>& describe)
    : model_(std::move(model)), material_(std::move(material)), numbering_(*model_, extra) {
    const Mesh& mesh = *model_->mesh;
    attached_.assign(numbering_.size(), 0);
    std::vector<int> dofs;
    const bool enriched = model_->enrichment != nullptr;
    if (enriched) enrichedIndex_.assign(model_->elements.size(), -1);
    LawCache laws(*material_);
    for (size_t e = 0; e < model_->elements.size(); ++e) {
        const auto& element = model_->elements[e];
        const IsotropicLaw& law = laws.of(element);
        if (enriched && model_->enrichment->isEnriched(element.cell) && describe && !describe(element.cell)) {
            enrichedIndex_[e] = kNotDescribed;
        } else if (enriched && model_->enrichment->isEnriched(element.cell)) {
            enrichedIndex_[e] = static_cast<int>(enrichedIntegrations_.size());
            model_->enrichment->integration(element.cell, enrichedIntegrations_.emplace_back());
            ElementIntegration& ei = enrichedIntegrations_.back();
            // The crack-tip fields are not kept: A, B and Phi are 108 doubles a point for the ~10^6
            // points of a 3D front's elements (ssnv185c: 290 MB), refilled by integrationOf.
            std::vector<double>().swap(ei.tipA);
            std::vector<double>().swap(ei.tipB);
            tipLaws_.emplace_back(law.lambdaEff, law.mu);
            markAttached(enrichedIntegrations_.back(), dofs);
        } else {
            for (int node : mesh.cellNodes(element.cell))
                for (int c = 0; c < numbering_.dim(); ++c) attached_[numbering_.dof(node, 0, c)] = 1;
        }
    }
}

// An enriched slot is used when its psi is not zero at one point at least.
void Discretisation::markAttached(const ElementIntegration& x, std::vector<int>& dofs) {
    localDofs(*model_->mesh, numbering_, x, dofs);
    int i = 0;
    for (int a = 0; a < x.nodeCount; ++a) {
        for (int k = 0; k < x.slots[a]; ++k) {
            bool used = k == 0;
            for (size_t p = 0; p < x.refPoints.size() && !used; ++p) used = x.multiplier(int(p), a, k) != 0.0;
            for (int c = 0; c < numbering_.dim(); ++c, ++i)
                if (used) attached_[dofs[i]] = 1;
        }
        if (x.tipAt(a))  // the crack-tip unknowns: their field is not zero in a tip-enriched element
            for (int c = 0; c < numbering_.dim(); ++c, ++i) attached_[dofs[i]] = 1;
    }
}

namespace {

[[noreturn]] void notDescribed(size_t e) {
    throw InternalError("X-FEM element " + std::to_string(e) + " was not described by this Discretisation");
}

}  // namespace

const ElementIntegration& Discretisation::integrationOf(size_t e, ElementIntegration& scratch) const {
    if (!enrichedIndex_.empty() && enrichedIndex_[e] == kNotDescribed) notDescribed(e);
    if (isEnriched(e)) {
        const ElementIntegration& stored = enrichedIntegrations_[size_t(enrichedIndex_[e])];
        if (!stored.hasTip()) return stored;
        scratch.describeAs(stored);
        model_->enrichment->tipFields(stored.cell, tipLaws_[size_t(enrichedIndex_[e])], scratch);
        return scratch;
    }
    classicalIntegration(*model_->mesh, model_->elements[e].cell, false, scratch);
    return scratch;
}

size_t Discretisation::pointCount(size_t e) const {
    if (!enrichedIndex_.empty() && enrichedIndex_[e] == kNotDescribed) notDescribed(e);
    if (isEnriched(e)) return enrichedIntegrations_[enrichedIndex_[e]].refPoints.size();
    return stiffnessRule(model_->mesh->cellTypes[model_->elements[e].cell]).points.size();
}

void Discretisation::distribute(int processes, int rank) {
    std::vector<int> cells, weights;
    for (size_t e = 0; e < elementCount(); ++e) {
        cells.push_back(model_->elements[e].cell);
        weights.push_back(static_cast<int>(pointCount(e)));  // X-FEM cells weigh their sub-cells' points
    }
    // Rank 0's partition for every process (METIS's fixed seed makes it the same run after run).
    mpi::collectively([&] {
        if (rank == 0) owner_ = partitionCells(mesh(), cells, weights, dim(), processes);
    });
    owner_.resize(elementCount());
    mpi::broadcast(owner_);
    rank_ = rank, processes_ = processes;
    cellElement_.assign(size_t(mesh().cellCount()), -1);
    for (size_t e = 0; e < elementCount(); ++e) cellElement_[size_t(cells[e])] = static_cast<int>(e);
}

bool Discretisation::ownsCell(int cell) const {
    if (owner_.empty()) return true;
    const int e = cell >= 0 && size_t(cell) < cellElement_.size() ? cellElement_[size_t(cell)] : -1;
    return e >= 0 && owner_[size_t(e)] == rank_;
}

std::vector<int> Discretisation::elementsPerProcess() const {
    std::vector<int> count(owner_.empty() ? 0 : size_t(processes_), 0);
    for (int p : owner_) ++count[size_t(p)];
    return count;
}

}  // namespace ma
