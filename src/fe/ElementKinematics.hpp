#pragma once
// Geometry of one element at its integration points: shape values, physical gradients, weights.
// Written once against ElementIntegration, so classical and X-FEM elements share it.
#include <array>
#include <span>
#include <vector>

#include "fe/ElementIntegration.hpp"
#include "fe/Model.hpp"

namespace ma {

// The classical description of an element (its Gauss rule, slot 0 only).
void classicalIntegration(const Mesh& mesh, int cell, bool boundary, ElementIntegration& out);
// The description of the model's element on `cell`: X-FEM when the enrichment says so.
void elementIntegration(const Model& model, int cell, bool boundary, ElementIntegration& out);

struct PointGeometry {
    int nodeCount = 0;
    std::vector<double> N;                      // N[p * n + a]
    std::vector<double> gradN;                  // gradN[(p * n + a) * 3 + j], physical (volume elements only)
    std::vector<double> weight;                 // physical weight (|J| included)
    std::vector<std::array<double, 3>> xyz;     // physical point
    std::vector<std::array<double, 3>> normal;  // unit normal by node order (skin elements only)
};

// Fills `geo` for the points of `integration` on `cell`. `spaceDim` is the model dimension
// (2: cells in the x-y plane). Volume cells: gradients; skin cells: normals and surface weights.
// NumericalError naming the cell when the Jacobian is not positive (volume) or zero (skin).
void computePointGeometry(const Mesh& mesh, int cell, int spaceDim, bool boundary,
                          const ElementIntegration& integration, PointGeometry& geo);

}  // namespace ma
