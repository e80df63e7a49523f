#pragma once
// The points of a 3D crack front as code_aster's X-FEM post-processing sees them (the fiss_xfem's
// FONDFISS and BASEFOND, post_k1_k2_k3_ops' get_coor_xfem / get_direction_xfem): each point of front
// NUME_FOND with its curvilinear abscissa, the normal to the crack (VNOR, the interpolated GRLNNO,
// towards increasing LSN), the propagation direction (VDIR, the interpolated GRLTNO made orthogonal
// to VNOR) and the tip cell size at the point (FOND_TAILLE_R, xtailm: the largest projection on
// VDIR of an edge of the tip cells that contain the point).
#include <array>
#include <vector>

#include "core/Vec3.hpp"
#include "mesh/Mesh.hpp"
#include "xfem/Crack.hpp"

namespace ma::fracture {

struct FrontPoint {
    Vec3 point{};
    double abscissa = 0.0;
    Vec3 normal{}, direction{};
    double cellSize = 0.0;
};

// Front `numeFond` (1-based) of a 3D crack; UserError when there is no such front or the level-set
// gradients vanish at a point.
std::vector<FrontPoint> frontPoints3D(const Mesh& mesh, const xfem::Crack& crack, int numeFond);

// code_aster's xtailm: the largest projection on `direction` of an edge of the tip cells that hold
// the point x (a front point on a face belongs to the two cells of the face).
double tipCellSize(const Mesh& mesh, const xfem::Crack& crack, const Vec3& x, const Vec3& direction);

// NB_POINT_FOND: `count` points evenly spaced in abscissa along the front, coordinates and bases
// interpolated linearly between the front's points (InterpolFondFiss, InterpolBaseFiss); the cell
// sizes are those of the nearer front point.
std::vector<FrontPoint> resampleFront(const std::vector<FrontPoint>& front, int count);

}  // namespace ma::fracture
