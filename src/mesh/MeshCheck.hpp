#pragma once
// What LIRE_MAILLAGE checks on the mesh it read (docs/mesh.md "Checks"): the coordinates, always,
// and VERI_MAIL, code_aster's chckma (orphan nodes, cells with a repeated node, double cells,
// flat cells).
#include <string>
#include <vector>

#include "core/Message.hpp"
#include "mesh/Mesh.hpp"

namespace ma {

// The geometry's range: the finite elements form products of up to three lengths (volumes,
// Jacobian determinants) and of those with the material's moduli, so a mesh must stay well inside
// double precision (1e±308): coordinates of magnitude at most kCoordinateLimit, and an extent
// (largest side of the bounding box) of at least 1 / kCoordinateLimit.
inline constexpr double kCoordinateLimit = 1e50;

// UserError naming the node of a non-finite coordinate (NaN, Inf), or of a coordinate beyond
// kCoordinateLimit, or the extent when the mesh is smaller than 1 / kCoordinateLimit. `path`
// names the mesh file.
void checkCoordinates(const Mesh& mesh, const std::string& path);

// VERI_MAIL/VERIF='OUI' as code_aster's chckma: nodes of no cell (alarm), double cells, the same
// nodes twice under two names (alarm MODELISA8_13 naming both), flat cells whose shortest distance
// between two of their nodes is below `aplat` times the longest (alarm MODELISA8_15). A cell with
// the same node twice is a UserError, as code_aster stops on it (MODELISA4_10). One alarm per
// finding kind, with the count and the first cells. Runs after checkCoordinates (squared lengths).
std::vector<FormattedMessage> veriMail(const Mesh& mesh, const std::string& path, double aplat);

}  // namespace ma
