#pragma once
// Values of a displacement field at the integration points of a model, with their physical
// coordinates and weights: what POST_ERREUR integrates. Classical elements use their own
// quadrature (commands_spec.md §5.4); X-FEM elements the points of their sub-cells.
#include <array>
#include <vector>

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
std::vector<DisplacementSample> sampleDisplacement(const Model& model, const NodalField& depl,
                                                   const std::vector<int>& cells);

// The same for the elements model.elements[first, last) whose cell is flagged in `wanted` (every
// cell when `wanted` is empty), appended to `out`: POST_ERREUR goes through a large model in
// batches of elements instead of holding every sample at once.
void appendDisplacementSamples(const Model& model, const NodalField& depl, const std::vector<char>& wanted,
                               size_t first, size_t last, std::vector<DisplacementSample>& out);

}  // namespace ma
