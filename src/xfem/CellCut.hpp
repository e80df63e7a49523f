#pragma once
// Sub-division of one X-FEM cell into integration sub-cells by its interfaces, crack after crack
// (xfem_spec §3.5). Everything is done in the parent's REFERENCE coordinates: level sets at new
// points are interpolated with the parent shape functions, sub-cells are simplices of the parent
// reference element, and their Gauss points need no inverse mapping.
#include <array>
#include <vector>

#include "mesh/Mesh.hpp"

namespace ma::xfem {

class Crack;

struct CutPoint {
    std::array<double, 3> ref{};  // parent reference coordinates
    int parentNode = -1;          // local node number when the point is a node of the parent
    std::vector<double> lsn;      // level set of every crack of CellCut::lsnCracks
};

struct SubCell {
    std::array<int, 4> vertices{};       // CutPoint indices (dimension + 1 used), positive orientation
    std::vector<signed char> heaviside;  // per local crack: -1, +1, or 0 (forbidden side of a branch)
};

struct CellCut {
    int cell = -1;
    CellType type = CellType::QUAD4;  // parent type
    int dim = 2;                      // sub-cell (= parent) topological dimension
    bool skin = false;                // boundary cell of the model
    std::vector<int> cracks;          // local cracks: indices in the model's crack list, in order
    // Cracks whose level set is carried by the points: the local ones first, then the masters of
    // local branches that are not local themselves.
    std::vector<const Crack*> lsnCracks;
    std::vector<CutPoint> points;  // parent nodes first (in local order), then new points
    std::vector<SubCell> subcells;
    int droppedDegenerate = 0;  // zero-measure pieces removed while cutting

    int vertexCount() const { return dim + 1; }
    int parentNodeCount() const { return nodeCount(type); }
    // Reference measure of a sub-cell (length, area or volume in parent reference coordinates).
    double referenceMeasure(int s) const;
};

// Cuts `cell` by the cracks `local` (model indices `localIndex`, same order). `outsideSign` is used
// for skin sub-cells lying on an interface (sign of the adjacent volume's level set, per local
// crack; empty for volume cells).
CellCut cutCell(const Mesh& mesh, int cell, const std::vector<const Crack*>& local, const std::vector<int>& localIndex,
                bool skin, const std::vector<int>& outsideSign);

}  // namespace ma::xfem
