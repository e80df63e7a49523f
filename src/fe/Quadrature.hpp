#pragma once
// Integration rules on the reference elements of mesh/ShapeFunctions.hpp, named as code_aster's
// integration families (FPG1, FPG4, NOEU ...; points and weights of bibfor/elements/elraga.F90).
// Weights sum to the reference measure (SEG 2, TRIA 1/2, QUAD 4, TETRA 1/6, HEXA 8).
//
//   SEG2   FPG1 FPG2 FPG3 FPG4            (Gauss-Legendre, degree 2n-1)
//          SIMP (3) SIMP1 (3) COTES (3) COTES1 (5) COTES2 (3)   (closed Newton-Cotes, X-FEM contact)
//   TRIA3  FPG1 (1) FPG3 (2) FPG4 (3, negative centre weight) FPG6 (4) FPG7 (5) FPG12 (6)
//          SIMP (1: vertices 1/30, edge midpoints 4/30)
//   QUAD4  FPG1 FPG4 (2x2) FPG9 (3x3)
//   TETRA4 FPG1 (1) FPG4 (2) FPG5 (3, negative centre weight) FPG15 (5) FPG24 (6)
//   HEXA8  FPG1 FPG8 (2x2x2) FPG27 (3x3x3)
//   every cell: NOEU (1: the vertices, weight = measure / vertex count)
// (degree of exactness in parentheses; unit-tested on monomials.)
#include <array>
#include <string>
#include <vector>

#include "mesh/CellType.hpp"

namespace ma {

struct QuadratureRule {
    std::string family;  // "FPG4"
    CellType cell = CellType::QUAD4;
    int degree = 0;  // polynomial degree integrated exactly
    std::vector<std::array<double, 3>> points;
    std::vector<double> weights;
    int size() const { return static_cast<int>(weights.size()); }
};

// The rule `family` on the reference element of `cell` (only the cell's shape matters: QUAD4's
// rules serve any quadrilateral). NotImplemented for unknown combinations.
const QuadratureRule& quadratureRule(CellType cell, const std::string& family);

// code_aster's default family ('RIGI') of the classical mechanical elements:
// TRIA3 FPG1, QUAD4 FPG4, TETRA4 FPG1, HEXA8 FPG8 (commands_spec §5.4), and for the boundary
// elements carrying pressure SEG2 FPG2, TRIA3 FPG3 (3D faces), QUAD4 FPG4.
const QuadratureRule& stiffnessRule(CellType cell, bool boundary = false);

}  // namespace ma
