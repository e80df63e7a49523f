#pragma once
// The surface loads of AFFE_CHAR_MECA(_F): PRES_REP on boundary cells (PRES, CISA_2D) and on the lips
// of X-FEM interfaces (FISSURE), FORCE_CONTOUR (edges of a plane model), FORCE_FACE (faces of a 3D
// model), FORCE_ARETE (edges of a 3D model). Included by src/commands files only.
#include "fe/MechanicalLoad.hpp"
#include "parser/KeywordTree.hpp"

namespace ma::mechanics {

// Reads those keywords of `kw` into `load` (its model set); `functions`: AFFE_CHAR_MECA_F.
void readSurfaceLoads(const KeywordSet& kw, bool functions, MechanicalLoad& load);

}  // namespace ma::mechanics
