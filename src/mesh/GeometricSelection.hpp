#pragma once
// The geometric selections of DEFI_GROUP that measure distances to a point or an axis: ENV_SPHERE
// and ENV_CYLINDRE (CREA_GROUP_NO), SPHERE and CYLINDRE (CREA_GROUP_MA). Semantics from code_aster's
// cgnoes, cgnoec, cgmasp, cgmacy (docs/mesh.md): nodes in increasing node number, cells in
// increasing cell number. In a plane mesh (effectiveDimension 2) only x and y count.
#include <string>
#include <vector>

#include "mesh/MeshQueries.hpp"

namespace ma {

// OPTION='ENV_SPHERE': nodes with | |x - centre| - radius | <= precision.
std::vector<int> nodesOnSphere(const Mesh& mesh, Vec3 centre, double radius, double precision);

// OPTION='ENV_CYLINDRE' (3D meshes): nodes whose distance d to the axis (point, direction) has
// |d - radius| <= precision. UserError on a zero direction.
std::vector<int> nodesOnCylinder(const Mesh& mesh, Vec3 point, Vec3 direction, double radius, double precision);

// CRIT_NOEUD of CREA_GROUP_MA OPTION='SPHERE', 'CYLINDRE', 'BANDE'.
enum class CellCriterion { AtLeastOne, All, Majority };
CellCriterion cellCriterion(const std::string& critNoeud);

// OPTION='SPHERE': cells with at least one, all, or at least (n+1)/2 of their n nodes at
// |x - centre| <= radius.
std::vector<int> cellsInSphere(const Mesh& mesh, Vec3 centre, double radius, CellCriterion criterion);

// OPTION='CYLINDRE' (3D meshes): the same with the distance to the axis. A cell one of whose
// nodes is the axis point itself is taken whatever the criterion, as code_aster does.
std::vector<int> cellsInCylinder(const Mesh& mesh, Vec3 point, Vec3 direction, double radius, CellCriterion criterion);

// The unit vector of ANGL_NAUT (degrees): 2D (alpha) -> (cos a, sin a, 0); 3D (alpha, beta) ->
// (cos a cos b, sin a cos b, -sin b).
Vec3 nauticalDirection(double alphaDeg, double betaDeg, int dimension);

}  // namespace ma
