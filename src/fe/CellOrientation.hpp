#pragma once
// Orientation of a mesh's volume cells (the cells of its dimension that have an element: TRIA3 and
// QUAD4 in 2D, TETRA4 and HEXA8 in 3D), read as code_aster reads it: the sign of det J at the
// points of the stiffness rule, in code_aster's node order. Every element integrates with |det J|,
// so a reversed cell (left-handed volume, clockwise 2D cell) gives the same element as its mirror
// numbering; only a distorted cell (det J changing sign among the points: code_aster's alarm
// MAILLAGE1_1) or a degenerate one (det J round-off for its size) is not a valid element.
#include <map>
#include <vector>

#include "mesh/Mesh.hpp"

namespace ma {

struct OrientationCensus {
    int dimension = 0;                 // of the cells counted (the mesh's effective dimension)
    std::map<CellType, int> total;     // volume cells per type
    std::map<CellType, int> reversed;  // of them, negative det J at every point
    std::vector<int> distorted;        // det J of both signs
    std::vector<int> degenerate;       // det J round-off for the cell's size at some point
    int reversedCount() const;
};

OrientationCensus orientationCensus(const Mesh& mesh);

}  // namespace ma
