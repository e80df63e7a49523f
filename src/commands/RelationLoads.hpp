#pragma once
// The kinematic conditions of AFFE_CHAR_MECA(_F) beyond DDL_IMPO: FACE_IMPO and ARETE_IMPO (the
// nodes of cells, DNOR/DTAN along the normal or tangent at each node), LIAISON_DDL (a linear
// relation between dofs) and LIAISON_GROUP (the same relation between paired nodes of two groups).
// Included by src/commands files only.
#include <vector>

#include "fe/MechanicalLoad.hpp"
#include "parser/KeywordTree.hpp"

namespace ma::mechanics {

// Reads those keywords of `kw` into `load` (its model set). `modelNodes`: nodes carrying unknowns.
void readRelationLoads(const KeywordSet& kw, bool functions, const std::vector<char>& modelNodes, MechanicalLoad& load);

}  // namespace ma::mechanics
