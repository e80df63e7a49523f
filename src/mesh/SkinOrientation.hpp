#pragma once
// MODI_MAILLAGE ORIE_PEAU_2D / ORIE_PEAU_3D (commands_spec §8.2): boundary cells are turned so
// that their normal (MeshQueries cellNormal) points out of the adjacent volume (3D) or surface
// (2D) cell.
#include <vector>

#include "mesh/Mesh.hpp"

namespace ma {

struct SkinOrientationReport {
    int checked = 0;     // boundary cells examined
    int reoriented = 0;  // of which turned over
};

// `skin`: cells of dimension bodyDim-1; `bodies`: the cells allowed as neighbours (empty: every
// cell of dimension bodyDim). UserError naming the cell when a skin cell has no neighbour, more
// than one (an internal face: give GROUP_MA_VOLU / GROUP_MA_SURF), or the wrong dimension.
SkinOrientationReport orientSkin(Mesh& mesh, const std::vector<int>& skin, const std::vector<int>& bodies, int bodyDim);

// Node permutation that reverses the orientation of a boundary cell (vertices reversed after the
// first one, mid-edge nodes following their edges): SEG2 [1,0], TRIA3 [0,2,1], QUAD8 ...
std::vector<int> reversedOrder(CellType t);

}  // namespace ma
