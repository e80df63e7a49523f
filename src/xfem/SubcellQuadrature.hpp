#pragma once
// Integration rules of the X-FEM sub-cells (xfem_spec §3.6) and miniaster's expert override,
// `miniaster run --subcell-quadrature DEGREE` (a run option, not a code_aster keyword: code_aster
// fixes these rules in its element catalogues).
#include <string>

#include "mesh/CellType.hpp"

namespace ma::xfem {

// Degrees the override accepts (`--subcell-quadrature`, registered by MODI_MODELE_XFEM, checks the same range).
constexpr int kMaxSubcellDegree = 6;

// Kind of sub-cell a rule is chosen for.
struct SubcellKind {
    int dim = 2;                 // sub-cell dimension (1: SEG2, 2: TRIA3, 3: TETRA4)
    bool skin = false;           // sub-cell of a boundary (skin) cell: carries boundary loads only
    bool severalCracks = false;  // the parent cell sees several interfaces (XHn element)
};

// code_aster's catalogue family: volume TRIA3 FPG12 (one interface) / FPG4 (several), TETRA4 FPG15
// / FPG5; skin SEG2 FPG4 / FPG2, skin TRIA3 faces FPG12.
std::string catalogueSubcellRule(const SubcellKind& kind);

// The lowest family of the simplex (TRIA3 or TETRA4) that integrates polynomials of `degree`
// exactly: TRIA3 1 FPG1, 2 FPG3, 3 FPG4, 4 FPG6, 5 FPG7, 6 FPG12; TETRA4 1 FPG1, 2 FPG4, 3 FPG5,
// 4 and 5 FPG15, 6 FPG24. UserError when the degree is outside 1..kMaxSubcellDegree.
std::string lowestRuleOfDegree(CellType simplex, int degree);

// The family used on a sub-cell of `kind` with the override `degree` (0: the catalogue). Only the
// volume sub-cells follow the degree; skin sub-cells keep the catalogue's rule (docs/xfem.md,
// "Quadrature": they are a handful of cells, and a lower rule would no longer integrate the face
// shape functions of a pressure exactly).
std::string subcellRule(const SubcellKind& kind, int degree);

// Degree, in the parent's reference coordinates, of the strains of its shape functions on an affine
// (parallelogram, parallelepiped) cell: TRIA3 and TETRA4 0, QUAD4 1, HEXA8 2. Sub-cells are affine
// in those coordinates, so a volume rule of lower degree no longer integrates the virtual strains
// exactly and uniform stress states are not reproduced (the patch test fails: measured on HEXA8
// with degree 1, docs/xfem.md).
int strainDegree(CellType parent);

// TRIA3/TETRA4 of a volume sub-cell, SEG2/TRIA3 of a skin sub-cell.
CellType subcellType(const SubcellKind& kind);

}  // namespace ma::xfem
