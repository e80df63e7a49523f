#pragma once
// Topology of the linear cells as X-FEM sees them: edges (for the level-set snapping, the cut
// cells and the junction test) and the primary split into simplices (xfem_spec §3.5.1).
#include <array>
#include <span>
#include <vector>

#include "mesh/CellType.hpp"
#include "mesh/Mesh.hpp"

namespace ma::xfem {

using Edge = std::array<int, 2>;

// Edges of a linear cell in local node numbers (0-based), in code_aster's edge order.
// NotImplemented for cells without X-FEM support (quadratic, pyramids, prisms).
std::span<const Edge> cellEdges(CellType type);

// Primary simplices of a cell (QUAD4 -> 2 triangles 1-2-4, 2-3-4; HEXA8 -> 6 tetrahedra;
// simplices themselves), local node numbers, each with dimension+1 entries.
std::vector<std::vector<int>> primarySimplices(CellType type);

// The simplex type of the sub-cells of a cell (SEG2, TRIA3 or TETRA4).
CellType simplexType(CellType type);

// True for the cell types X-FEM supports (SEG2, TRIA3, QUAD4, TETRA4, HEXA8).
bool xfemSupports(CellType type);

// Signed measure of the simplex with the given vertices (dim 1, 2 or 3), in the coordinates given
// (reference or physical). 2D: z ignored.
double simplexMeasure(int dim, std::span<const std::array<double, 3>> v);

// code_aster's characteristic length of a cell (loncar): SEG2 its length, QUAD4 and TRIA3
// sqrt(|P1P2| |P1P3|), TETRA4 the cube root of its three edges from P1, HEXA8 its diagonal P1P7.
double characteristicLength(const Mesh& mesh, int cell);

}  // namespace ma::xfem
