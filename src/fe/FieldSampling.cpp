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

void appendDisplacementSamples(const Model& model, const NodalField& depl, const std::vector<char>& wanted,
                               size_t first, size_t last, std::vector<DisplacementSample>& out,
                               const MaterialField* material) {
    const Mesh& mesh = *model.mesh;
    const int dim = model.dim;
    // Field component of each (slot, direction), -1 when the field lacks it (counts as 0).
    std::vector<int> component;
    auto componentIndex = [&](int slot, int c) {
        const size_t key = size_t(slot) * 3 + c;
        if (component.size() <= key) component.resize(key + 1, -2);
        if (component[key] == -2) component[key] = depl.componentIndex(displacementComponentName(slot, c));
        return component[key];
    };
    std::vector<int> tipComponent;  // K1, K2[, K3] in the field
    for (int c = 0; c < dim; ++c) tipComponent.push_back(depl.componentIndex(fmt::format("K{}", c + 1)));
    GeneralElementScratch scratch;
    std::vector<double> nodal;
    std::vector<char> carried;
    size_t stride = 1;  // slots per local node in `nodal`
    for (size_t e = first; e < last; ++e) {
        const auto& element = model.elements[e];
        if (!wanted.empty() && !wanted[element.cell]) continue;
        const bool enriched = model.enrichment && model.enrichment->isEnriched(element.cell);
        const int* nodes = mesh.connectivity.data() + mesh.cellOffsets[element.cell];
        // The element's nodal values by (local node, slot, direction), looked up once for all its
        // points (an X-FEM element has hundreds); `carried` is 0 where the field lacks the value.
        auto gather = [&](int nodeCount, const std::vector<int>& slots) {
            stride = slots.empty() ? 1 : size_t(*std::max_element(slots.begin(), slots.end()));
            nodal.assign(size_t(nodeCount) * stride * 3, 0.0);
            carried.assign(nodal.size(), 0);
            for (int a = 0; a < nodeCount; ++a)
                for (int k = 0; k < (slots.empty() ? 1 : slots[size_t(a)]); ++k)
                    for (int c = 0; c < dim; ++c) {
                        const int comp = componentIndex(k, c);
                        const size_t at = (size_t(a) * stride + size_t(k)) * 3 + size_t(c);
                        if (comp >= 0 && depl.has(nodes[a], comp)) nodal[at] = depl.at(nodes[a], comp), carried[at] = 1;
                    }
        };
        // Adds factor * U(local node a, slot) to s.u, from the element's values gathered below.
        auto add = [&](DisplacementSample& s, int a, int slot, double factor) {
            if (factor == 0.0) return;
            const size_t at = (size_t(a) * stride + size_t(slot)) * 3;
            for (int c = 0; c < dim; ++c)
                if (carried[at + size_t(c)]) s.u[c] += factor * nodal[at + size_t(c)];
        };
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
                gather(ei.nodeCount, ei.slots);
                return ei;
            },
            [&](const auto& ref, const auto& g) {  // classical: slot 0 only (psi = 1)
                using Ref = std::decay_t<decltype(ref)>;
                gather(Ref::nodes, {});
                for (int p = 0; p < Ref::points; ++p) {
                    DisplacementSample s{element.cell, g.xyz[p], g.weight[p], {}};
                    for (int a = 0; a < Ref::nodes; ++a) add(s, a, 0, ref.N[p][a]);
                    out.push_back(s);
                }
            },
            [&](const ElementIntegration& ei, const PointGeometry& geo) {
                const int n = ei.nodeCount;
                for (size_t p = 0; p < ei.refPoints.size(); ++p) {
                    DisplacementSample s{element.cell, geo.xyz[p], geo.weight[p], {}};
                    for (int a = 0; a < n; ++a) {
                        for (int k = 0; k < ei.slots[a]; ++k)
                            add(s, a, k, geo.N[p * n + a] * ei.multiplier(int(p), a, k));
                        if (ei.tipAt(a)) addTip(s, ei.tipValue(p, ei.tipGroupOf(a)), nodes[a], geo.N[p * n + a]);
                    }
                    out.push_back(s);
                }
            });
    }
}

}  // namespace ma
