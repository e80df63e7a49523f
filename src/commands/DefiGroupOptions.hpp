#pragma once
// DEFI_GROUP's OPTION= selections, read from one CREA_GROUP_MA / CREA_GROUP_NO occurrence: the
// geometric ones (mesh/GeometricSelection, mesh/LineOrdering, mesh/GroupSelection) and the X-FEM
// ones (FISS_XFEM, from the interfaces' enriched nodes and cells). Keyword checks follow
// code_aster's cgno*/cgma* routines (docs/mesh.md).
#include <vector>

#include "mesh/Mesh.hpp"
#include "parser/KeywordTree.hpp"

namespace ma::defi_group {

// The cells of CREA_GROUP_MA OPTION=...
std::vector<int> cellOption(const Mesh& mesh, const KeywordSet& occ);
// The nodes of CREA_GROUP_NO OPTION=..., in code_aster's order.
std::vector<int> nodeOption(const Mesh& mesh, const KeywordSet& occ);

}  // namespace ma::defi_group
