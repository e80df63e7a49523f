#pragma once
// Lagrange shape functions of the linear cells at arbitrary reference points.
//
// Reference elements (node order = the mesh's code_aster/VTK order):
//   SEG2   [-1, 1]                 nodes -1, +1
//   TRIA3  (0,0) (1,0) (0,1)       N = 1-x-y, x, y
//   QUAD4  [-1,1]^2                (-1,-1) (1,-1) (1,1) (-1,1)
//   TETRA4 (0,0,0) (1,0,0) (0,1,0) (0,0,1)   N = 1-x-y-z, x, y, z
//   HEXA8  [-1,1]^3                bottom face (z=-1) as QUAD4, then top face (z=+1)
// These are the coordinates stored in ElementIntegration::refPoints and
// GaussField::pointRefCoords. The X-FEM engine maps its sub-cell points with them.
#include <array>
#include <span>

#include "mesh/CellType.hpp"

namespace ma {

// True for the cells the elasticity engine has elements for (SEG2, TRIA3, QUAD4, TETRA4, HEXA8).
bool hasShapeFunctions(CellType type);
// Dimension of the reference element (1, 2 or 3).
int referenceDimension(CellType type);

// N[a] at reference point xi (xi has referenceDimension(type) meaningful entries).
void shapeValues(CellType type, const std::array<double, 3>& xi, std::span<double> N);
// dN[a * 3 + j] = dN_a / dxi_j (j < referenceDimension(type); other entries set to 0).
void shapeDerivatives(CellType type, const std::array<double, 3>& xi, std::span<double> dN);

// Reference coordinates of the nodes of the reference element.
std::span<const std::array<double, 3>> referenceNodes(CellType type);

// Physical point of reference point xi for a cell with node coordinates `nodes`.
std::array<double, 3> mapToPhysical(CellType type, std::span<const std::array<double, 3>> nodes,
                                    const std::array<double, 3>& xi);

// Inverse map (Newton) for a volume cell of the model's dimension (TRIA3/QUAD4 in the x-y plane,
// TETRA4/HEXA8 in space): reference point of physical point x. Exact for simplices; for
// QUAD4/HEXA8 Newton converges to 1e-14 relative on non-degenerate cells. Returns false when
// Newton did not converge (degenerate cell).
bool mapToReference(CellType type, std::span<const std::array<double, 3>> nodes, const std::array<double, 3>& x,
                    std::array<double, 3>& xi);

}  // namespace ma
