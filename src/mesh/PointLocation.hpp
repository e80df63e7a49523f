#pragma once
// The cell containing a point, and the point's reference coordinates in it: nodal values
// interpolated at a point given in a command (DEFI_FISS_XFEM JONCTION/POINT).
#include <array>
#include <span>
#include <vector>

#include "core/Vec3.hpp"
#include "mesh/Mesh.hpp"

namespace ma {

struct PointInCell {
    int cell = -1;  // -1: the point lies in no cell
    std::array<double, 3> xi{};
};

// The lowest-numbered cell of the mesh's highest dimension (among those with shape functions)
// that contains x, the reference element widened by 1e-10 of its size so that a point on a face
// of the mesh's boundary is inside. Scale-free: nothing but reference coordinates is compared.
// A 2D mesh ignores x's z.
PointInCell locatePoint(const Mesh& mesh, const Vec3& x);

// locatePoint, or for a point outside the mesh its projection on the nearest cell when that lies
// within maxDistance (code_aster's PROJ_CHAMP DISTANCE_MAX): the reference coordinates clamped to
// the reference element, the lowest-numbered of equally near cells.
PointInCell locateNearPoint(const Mesh& mesh, const Vec3& x, double maxDistance);

// sum_a N_a(xi) values[node a] over the nodes of the located cell.
double interpolateAt(const Mesh& mesh, const PointInCell& at, const std::vector<double>& values);
Vec3 interpolateAt(const Mesh& mesh, const PointInCell& at, const std::vector<Vec3>& values);

}  // namespace ma
