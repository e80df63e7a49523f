#pragma once
// Geometric questions about cells, shared by DEFI_GROUP, MODI_MAILLAGE and the mesh tools.
#include <array>
#include <span>
#include <vector>

#include "core/Vec3.hpp"
#include "mesh/Mesh.hpp"

namespace ma {

// Vertices come first in the internal node order; then mid-edge nodes, then face/volume centres.
int vertexCount(CellType t);
// Number of face/volume centre nodes (TRIA7, QUAD9, PENTA18, HEXA27); 0 otherwise.
int centreNodeCount(CellType t);

// 2 when every node has the same z (a plane mesh, whatever the file's space dimension), else 3.
int effectiveDimension(const Mesh& mesh);

// Centroid of the vertices of a cell.
Vec3 vertexCentroid(const Mesh& mesh, int cell);

// code_aster's normal of a boundary cell (not normalised): SEG (y2-y1, -(x2-x1), 0) from its
// first two nodes; TRIA/QUAD (P2-P1)x(P3-P1). Zero vector for other cells.
Vec3 cellNormal(const Mesh& mesh, int cell);

// The cells of dimension `dim` around each node (compressed rows), among `cells` (all when empty).
class NodeCellIndex {
public:
    NodeCellIndex(const Mesh& mesh, int dim, const std::vector<int>& cells = {});
    std::span<const int> cellsOf(int node) const {
        return {cells_.data() + start_[size_t(node)], size_t(start_[size_t(node) + 1] - start_[size_t(node)])};
    }

private:
    std::vector<int> start_, cells_;
};

}  // namespace ma
