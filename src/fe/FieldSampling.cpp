#include "fe/FieldSampling.hpp"

#include <algorithm>

#include "core/Error.hpp"
#include "fe/DofNumbering.hpp"
#include "fe/ElementKinematics.hpp"

namespace ma {

std::vector<DisplacementSample> sampleDisplacement(const Model& model, const NodalField& depl,
                                                   const std::vector<int>& cells) {
    const Mesh& mesh = *model.mesh;
    const int dim = model.dim;
    std::vector<char> wanted;
    if (!cells.empty()) {
        wanted.assign(mesh.cellCount(), 0);
        for (int c : cells) wanted.at(c) = 1;
    }
    // Field component of each (slot, direction), -1 when the field lacks it (counts as 0).
    std::vector<int> component;
    auto componentIndex = [&](int slot, int c) {
        const size_t key = size_t(slot) * 3 + c;
        if (component.size() <= key) component.resize(key + 1, -2);
        if (component[key] == -2) component[key] = depl.componentIndex(displacementComponentName(slot, c));
        return component[key];
    };
    std::vector<DisplacementSample> out;
    ElementIntegration ei;
    PointGeometry geo;
    for (const auto& element : model.elements) {
        if (!wanted.empty() && !wanted[element.cell]) continue;
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
    return out;
}

}  // namespace ma
