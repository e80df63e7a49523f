#include "fe/FieldSampling.hpp"

#include <algorithm>
#include <type_traits>

#include "core/Error.hpp"
#include "fe/ClassicalElement.hpp"
#include "fe/DofNumbering.hpp"
#include "fe/Enrichment.hpp"
#include "fe/ElementKinematics.hpp"

namespace ma {

std::vector<DisplacementSample> sampleDisplacement(const Model& model, const NodalField& depl,
                                                   const std::vector<int>& cells) {
    std::vector<char> wanted;
    if (!cells.empty()) {
        wanted.assign(model.mesh->cellCount(), 0);
        for (int c : cells) wanted.at(c) = 1;
    }
    std::vector<DisplacementSample> out;
    appendDisplacementSamples(model, depl, wanted, 0, model.elements.size(), out);
    return out;
}

void appendDisplacementSamples(const Model& model, const NodalField& depl, const std::vector<char>& wanted,
                               size_t first, size_t last, std::vector<DisplacementSample>& out) {
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
    ElementIntegration ei;
    PointGeometry geo;
    for (size_t e = first; e < last; ++e) {
        const auto& element = model.elements[e];
        if (!wanted.empty() && !wanted[element.cell]) continue;
        const bool enriched = model.enrichment && model.enrichment->isEnriched(element.cell);
        // Classical elements: fixed-size geometry, slot 0 only (psi = 1).
        const bool fixedSize = !enriched && classical::dispatch(mesh.cellTypes[element.cell], dim, [&](const auto& ref) {
            using Ref = std::decay_t<decltype(ref)>;
            classical::Geometry<Ref> g;
            classical::computeGeometry(ref, mesh, element.cell, g);
            const int* nodes = mesh.connectivity.data() + mesh.cellOffsets[element.cell];
            for (int p = 0; p < Ref::points; ++p) {
                DisplacementSample s;
                s.cell = element.cell;
                s.xyz = g.xyz[p];
                s.weight = g.weight[p];
                for (int a = 0; a < Ref::nodes; ++a) {
                    const double factor = ref.N[p][a];
                    if (factor == 0.0) continue;
                    for (int c = 0; c < Ref::dim; ++c) {
                        const int comp = componentIndex(0, c);
                        if (comp >= 0 && depl.has(nodes[a], comp)) s.u[c] += factor * depl.at(nodes[a], comp);
                    }
                }
                out.push_back(s);
            }
        });
        if (fixedSize) continue;
        elementIntegration(model, element.cell, false, ei);
        computePointGeometry(mesh, element.cell, dim, false, ei, geo);
        const auto nodes = mesh.cellNodes(element.cell);
        const int n = ei.nodeCount;
        for (size_t p = 0; p < ei.refPoints.size(); ++p) {
            DisplacementSample s;
            s.cell = element.cell;
            s.xyz = geo.xyz[p];
            s.weight = geo.weight[p];
            for (int a = 0; a < n; ++a) {
                const double Na = geo.N[p * n + a];
                for (int k = 0; k < ei.slots[a]; ++k) {
                    const double factor = Na * ei.multiplier(int(p), a, k);
                    if (factor == 0.0) continue;
                    for (int c = 0; c < dim; ++c) {
                        const int comp = componentIndex(k, c);
                        if (comp >= 0 && depl.has(nodes[a], comp)) s.u[c] += factor * depl.at(nodes[a], comp);
                    }
                }
            }
            out.push_back(s);
        }
    }
}

}  // namespace ma
