#pragma once
// The selections of DEFI_GROUP (commands_spec §8.1). Each returns entity indices (0-based) in
// the order code_aster lists them; the command names and stores the groups.
#include <string>
#include <vector>

#include "mesh/MeshQueries.hpp"

namespace ma {

// CRIT_NOEUD of CREA_GROUP_NO / GROUP_MA.
enum class NodeCriterion { All, Vertices, MidNodes, Centres };
// Nodes of the cells, in increasing node number.
std::vector<int> nodesOfCells(const Mesh& mesh, const std::vector<int>& cells, NodeCriterion crit = NodeCriterion::All);

// OPTION='PLAN': nodes with |(x - point).n| <= precision, n = normal normalised; in a plane mesh
// (effectiveDimension 2) only x and y count. UserError on a zero normal.
std::vector<int> nodesOnPlane(const Mesh& mesh, Vec3 point, Vec3 normal, double precision);

// OPTION='FACE_NORMALE': boundary cells (SEG* in a plane mesh, TRIA*/QUAD* in 3D) whose normal
// makes an angle below anglePrecisionDeg with `direction`; checkSign rejects n.v <= 0.
std::vector<int> cellsWithNormal(const Mesh& mesh, Vec3 direction, double anglePrecisionDeg, bool checkSign);

// OPTION='BANDE': cells of any dimension with at least one ("AU_MOINS_UN"), all ("TOUS") or at
// least half ("MAJORITE") of their nodes at |(x - point).n| <= dist.
std::vector<int> cellsInBand(const Mesh& mesh, Vec3 point, Vec3 normal, double dist, const std::string& criterion);

// TYPE_MAILLE filter: "TOUT", "0D".."3D" or a code_aster type name ("QUAD4").
std::vector<int> filterCellType(const Mesh& mesh, const std::vector<int>& cells, const std::string& typeFilter);

// Order-preserving set operations on member lists (first list's order, then new members).
std::vector<int> intersectionOf(const std::vector<const std::vector<int>*>& lists);
std::vector<int> unionOf(const std::vector<const std::vector<int>*>& lists);
std::vector<int> differenceOf(const std::vector<const std::vector<int>*>& lists);

}  // namespace ma
