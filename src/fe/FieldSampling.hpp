#pragma once
// Values of a displacement field at the integration points of a model, with their physical
// coordinates and weights: what POST_ERREUR integrates. Classical elements use their own
// quadrature (commands_spec.md §5.4); X-FEM elements the points of their sub-cells.
#include <array>
#include <vector>

#include "fe/ElementIntegration.hpp"
#include "fe/Material.hpp"
#include "fe/Model.hpp"
#include "fields/Fields.hpp"

namespace ma {

struct DisplacementSample {
    int cell = -1;
    std::array<double, 3> xyz{};
    double weight = 0.0;        // physical weight (|J| included; 2D: unit thickness)
    std::array<double, 3> u{};  // DX, DY, DZ (DZ = 0 in 2D)
};

// Samples on the model's elements whose cell is in `cells` (all elements when `cells` is empty).
// Crack-tip enriched elements need the material (their fields depend on kappa and mu): UserError
// when `material` is null there.
std::vector<DisplacementSample> sampleDisplacement(const Model& model, const NodalField& depl,
                                                   const std::vector<int>& cells,
                                                   const MaterialField* material = nullptr);

// The same for the elements model.elements[first, last) whose cell is flagged in `wanted` (every
// cell when `wanted` is empty), appended to `out`: POST_ERREUR goes through a large model in
// batches of elements instead of holding every sample at once.
void appendDisplacementSamples(const Model& model, const NodalField& depl, const std::vector<char>& wanted,
                               size_t first, size_t last, std::vector<DisplacementSample>& out,
                               const MaterialField* material = nullptr);

// The material's law applied to a crack-tip enriched element description (ElementIntegration::
// tipPhi); nothing for other elements. UserError naming the cell when `material` is null.
void applyMaterialToTip(const Model& model, const MaterialField* material, const ModelElement& element,
                        ElementIntegration& ei);

}  // namespace ma
