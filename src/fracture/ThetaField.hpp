#pragma once
// The virtual crack extension theta of CALC_G at a 2D crack tip (code_aster's gcou2d for a
// fiss_xfem): at each node, theta = g/|g| (g the node's GRLTNO, the propagation direction) times 1
// within R_INF of the tip, 0 beyond R_SUP, linear in the distance in between; cells interpolate it.
// Without R_INF/R_SUP code_aster takes 2 and 4 times the tip's cell size (TAILLE_R, xtailm).
#include <vector>

#include "core/Vec3.hpp"
#include "fracture/DomainIntegrals.hpp"
#include "mesh/Mesh.hpp"
#include "xfem/Crack.hpp"

namespace ma::fracture {

struct TipPoint {
    Vec3 point{};
    FrontFrame frame;       // e1 the interpolated GRLTNO at the tip, e2 = z x e1
    double cellSize = 0.0;  // TAILLE_R: max over the tip cells' edges of |edge . e1|
};

// Front NUME_FOND (1-based) of a 2D crack; UserError when it has no such front.
TipPoint tipPoint2D(const Mesh& mesh, const xfem::Crack& crack, const std::vector<Vec3>& grlt, int numeFond);

// theta at every node; UserError naming the node where GRLTNO vanishes inside R_SUP (XFEM_12).
std::vector<Vec3> thetaField2D(const Mesh& mesh, const Vec3& tip, const std::vector<Vec3>& grlt, double rInf,
                               double rSup);

}  // namespace ma::fracture
