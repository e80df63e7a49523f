#pragma once
// Conformity of a mesh's cells of the highest dimension: a face between two volume cells (an edge
// between two 2D cells) must be a face of both. Where it is not (a quadrangle cut along different
// diagonals on its two sides, a node hanging on an edge), the two cells' faces there are each on
// no other cell and overlap each other: the finite element field is discontinuous across them.
#include <vector>

#include "mesh/Mesh.hpp"

namespace ma {

struct ConformityReport {
    int dimension = 0;            // of the cells examined (2 or 3)
    int unsharedFaces = 0;        // faces of one cell only (the boundary, and the faults)
    std::vector<int> faultCells;  // cells owning a face that overlaps another unshared face
    int overlappingFaces = 0;     // unshared faces that overlap another one
};

ConformityReport meshConformity(const Mesh& mesh);

}  // namespace ma
