#pragma once
// The ordered node groups of DEFI_GROUP CREA_GROUP_NO: SEGM_DROI_ORDO (nodes sorted along a
// straight segment, code_aster's oreino) and NOEUD_ORDO (the nodes of a chain of SEG cells walked
// from its origin, code_aster's cgnoor and ornofd). docs/mesh.md gives the rules.
#include <vector>

#include "mesh/MeshQueries.hpp"

namespace ma {

// SEGM_DROI_ORDO: `nodes` sorted by their abscissa along [origin, extremity] (equal abscissae keep
// their order). UserError, naming the node, when a node lies farther than `precision` from the
// line (relative: the distance divided by |AB|), farther from A than B is, or two nodes share an
// abscissa; code_aster stops there too.
std::vector<int> orderAlongSegment(const Mesh& mesh, std::vector<int> nodes, int origin, int extremity,
                                   double precision, bool relative);

// NOEUD_ORDO: the line's ends and how to orient it; -1 = not given.
struct LineEnds {
    int origin = -1;
    int extremity = -1;
    Vec3 orientation{0, 0, 0};  // VECT_ORIE (closed lines with origin == extremity)
    bool anyOrigin = false;     // ORIGINE='SANS': a closed line starts at its first cell's first node
};

// The nodes of `cells` (SEG2, SEG3 or SEG4 of one type, one open or closed line) from the origin to
// the other end, mid-nodes included; a closed line lists its origin first and last.
std::vector<int> nodesAlongLine(const Mesh& mesh, std::vector<int> cells, const LineEnds& ends);

}  // namespace ma
