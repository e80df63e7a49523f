#pragma once
// gmsh's legacy list-based post-processing format ("POS ASCII", versions 1.0 and 1.2), as
// code_aster's IMPR_RESU FORMAT='GMSH' writes it (docs/visualisation.md, "File layout" and the
// cells): one $View per field component (scalar), vector or tensor; every
// record carries its nodes' coordinates, so the file needs no mesh.
#include <string>
#include <vector>

#include "mesh/Mesh.hpp"

namespace ma::gmsh {

enum class ViewKind { Scalar, Vector, Tensor };

struct View {
    std::string name;  // no blanks (gmsh reads it with %s)
    ViewKind kind = ViewKind::Scalar;
    std::vector<double> times;  // one per step
    // Values per step: perCell ? cellCount : nodeCount tuples of rawComponents() values
    // (scalar 1, vector 3, tensor 6 in the order XX YY ZZ XY XZ YZ).
    bool perCell = false;
    std::vector<std::vector<double>> steps;
    std::vector<int> cells;  // the cells written, in mesh order
    int rawComponents() const { return kind == ViewKind::Scalar ? 1 : kind == ViewKind::Vector ? 3 : 6; }
};

// The file header ($PostFormat), once per file; version 1 (= 1.0) or 2 (= 1.2).
std::string header(int version);

// One $View block. Cells of the types code_aster does not write (PYRA13) are left out and listed
// in `skipped`; quadratic cells are split into linear ones as code_aster's irgmtb does.
std::string view(const Mesh& mesh, const View& v, int version, std::vector<CellType>* skipped = nullptr);

// The mesh alone in gmsh's mesh format 1.0 ($NOD/$ELM), as code_aster's irmgms writes it for
// IMPR_RESU(FORMAT='GMSH', RESU=_F(MAILLAGE=...)): nodes and cells numbered from 1 in mesh order, the
// physical and elementary region of a cell the number of its last cell group (a group named GM<n>
// has number n, the k-th other group k + max(10000, the largest such n); 10000 without a group).
// Linear cells only (NotImplemented for quadratic ones, which code_aster splits).
std::string meshFormat1(const Mesh& mesh);

// code_aster's number format E15.7E3 (" 1.0000000E+000"); |v| <= 1e-99 is written as 0.
std::string fortranE(double v);

}  // namespace ma::gmsh
