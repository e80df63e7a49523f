#include "fe/FieldSampling.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <type_traits>

#include "core/Error.hpp"
#include "fe/DofNumbering.hpp"
#include "fe/ElasticityKernels.hpp"
#include "fe/ElementLoop.hpp"
#include "fe/Enrichment.hpp"

namespace ma {

void applyMaterialToTip(const Model& model, const MaterialField* material, const ModelElement& element,
                        ElementIntegration& ei) {
    if (!ei.hasTip()) return;
    if (!material)
        throw UserError(fmt::format("cell {} is crack-tip enriched: its displacement needs the material (CHAM_MATER)",
                                    model.mesh->cellNames[size_t(element.cell)]));
    const Material& m = material->at(element.cell);
    const IsotropicLaw law = IsotropicLaw::from(m, element.modelisation, m.name);
    applyTipLaw(ei, law.lambdaEff, law.mu);
}

std::vector<DisplacementSample> sampleDisplacement(const Model& model, const NodalField& depl,
                                                   const std::vector<int>& cells, const MaterialField* material) {
    std::vector<char> wanted;
    if (!cells.empty()) {
        wanted.assign(model.mesh->cellCount(), 0);
        for (int c : cells) wanted.at(c) = 1;
    }
    std::vector<DisplacementSample> out;
    appendDisplacementSamples(model, depl, wanted, 0, model.elements.size(), out, material);
    return out;
}

namespace {

// One element's nodal values of a displacement field by (local node, slot, direction), looked up
// once for all its points (an X-FEM element has hundreds).
class ElementNodalValues {
public:
    explicit ElementNodalValues(const NodalField& depl, int dim) : depl_(depl), dim_(dim) {}

    // The values of the nodes `nodes` (slots[a] slots each; one when `slots` is empty).
    void gather(const int* nodes, int nodeCount, const std::vector<int>& slots) {
        stride_ = slots.empty() ? 1 : size_t(*std::max_element(slots.begin(), slots.end()));
        values_.assign(size_t(nodeCount) * stride_ * 3, 0.0);
        carried_.assign(values_.size(), 0);
        for (int a = 0; a < nodeCount; ++a)
            for (int k = 0; k < (slots.empty() ? 1 : slots[size_t(a)]); ++k)
                for (int c = 0; c < dim_; ++c) {
                    const int comp = componentOf(k, c);
                    const size_t at = index(a, k) + size_t(c);
                    if (comp >= 0 && depl_.has(nodes[a], comp))
                        values_[at] = depl_.at(nodes[a], comp), carried_[at] = 1;
                }
    }

    // Adds factor * U(local node a, slot) to u (the components the field carries).
    void add(std::array<double, 3>& u, int a, int slot, double factor) const {
        if (factor == 0.0) return;
        const size_t at = index(a, slot);
        for (int c = 0; c < dim_; ++c)
            if (carried_[at + size_t(c)]) u[size_t(c)] += factor * values_[at + size_t(c)];
    }

private:
    size_t index(int a, int slot) const { return (size_t(a) * stride_ + size_t(slot)) * 3; }
    // The field's component of (slot, direction), -1 when the field lacks it.
    int componentOf(int slot, int c) {
        const size_t key = size_t(slot) * 3 + size_t(c);
        if (components_.size() <= key) components_.resize(key + 1, -2);
        if (components_[key] == -2) components_[key] = depl_.componentIndex(displacementComponentName(slot, c));
        return components_[key];
    }

    const NodalField& depl_;
    int dim_;
    std::vector<int> components_;
    std::vector<double> values_;
    std::vector<char> carried_;  // 0 where the field lacks the value
    size_t stride_ = 1;          // slots per local node
};

}  // namespace

void appendDisplacementSamples(const Model& model, const NodalField& depl, const std::vector<char>& wanted,
                               size_t first, size_t last, std::vector<DisplacementSample>& out,
                               const MaterialField* material) {
    const Mesh& mesh = *model.mesh;
    const int dim = model.dim;
    std::vector<int> tipComponent;  // K1, K2[, K3] in the field
    for (int c = 0; c < dim; ++c) tipComponent.push_back(depl.componentIndex(fmt::format("K{}", c + 1)));
    GeneralElementScratch scratch;
    ElementNodalValues nodal(depl, dim);
    for (size_t e = first; e < last; ++e) {
        const auto& element = model.elements[e];
        if (!wanted.empty() && !wanted[element.cell]) continue;
        const bool enriched = model.enrichment && model.enrichment->isEnriched(element.cell);
        const int* nodes = mesh.connectivity.data() + mesh.cellOffsets[element.cell];
        // Adds N_a * Phi * K(node) to s.u.
        auto addTip = [&](DisplacementSample& s, const double* phi, int node, double Na) {
            for (int m = 0; m < dim; ++m) {
                const int comp = tipComponent[size_t(m)];
                if (comp < 0 || !depl.has(node, comp)) continue;
                const double K = depl.at(node, comp);
                for (int c = 0; c < dim; ++c) s.u[size_t(c)] += Na * phi[c * 3 + m] * K;
            }
        };
        visitVolumeElement(
            mesh, dim, element.cell, enriched, scratch,
            [&](ElementIntegration& ei) -> const ElementIntegration& {
                elementIntegration(model, element.cell, false, ei);
                applyMaterialToTip(model, material, element, ei);
                nodal.gather(nodes, ei.nodeCount, ei.slots);
                return ei;
            },
            [&](const auto& ref, const auto& g) {  // classical: slot 0 only (psi = 1)
                using Ref = std::decay_t<decltype(ref)>;
                nodal.gather(nodes, Ref::nodes, {});
                for (int p = 0; p < Ref::points; ++p) {
                    DisplacementSample s{element.cell, g.xyz[p], g.weight[p], {}};
                    for (int a = 0; a < Ref::nodes; ++a) nodal.add(s.u, a, 0, ref.N[p][a]);
                    out.push_back(s);
                }
            },
            [&](const ElementIntegration& ei, const PointGeometry& geo) {
                const int n = ei.nodeCount;
                for (size_t p = 0; p < ei.refPoints.size(); ++p) {
                    DisplacementSample s{element.cell, geo.xyz[p], geo.weight[p], {}};
                    for (int a = 0; a < n; ++a) {
                        for (int k = 0; k < ei.slots[a]; ++k)
                            nodal.add(s.u, a, k, geo.N[p * n + a] * ei.multiplier(int(p), a, k));
                        if (ei.tipAt(a)) addTip(s, ei.tipValue(p, ei.tipGroupOf(a)), nodes[a], geo.N[p * n + a]);
                    }
                    out.push_back(s);
                }
            });
    }
}

}  // namespace ma
