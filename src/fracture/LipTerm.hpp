#pragma once
// The lip-pressure term of the theta method (code_aster's xsifle / xsifl1 for CALC_G and CALC_K_G on
// X-FEM elements with PRES_REP FISSURE): on each loaded lip, with t its traction (t = -p m +
// c (-m_y, m_x), m the normal out of the lip's material) and u the displacement of that lip,
//
//   G    += sum_lips integral [ t . u div(theta) + (grad t . theta) . u ] dS
//   I(a) += sum_lips integral [ t . ua div(theta) + (grad t . theta) . ua ] dS
//
// ua the auxiliary Williams displacement of unit K at the point (r, +pi on the lip whose material
// lies on the e2 side, -pi on the other). K1 = E* I(I) / 2, K2 = E* I(II) / 2, K3 = mu I(III), as
// the volume terms. grad t is zero for a constant pressure (code_aster's only case: it refuses a
// function pressure, XFEM_99); a function pressure's gradient is that of its values at the cell's
// nodes interpolated. docs/cracks.md, "The lip-pressure term".
#include <functional>
#include <span>
#include <vector>

#include "core/Vec3.hpp"
#include "fe/Discretisation.hpp"
#include "fe/LoadCase.hpp"
#include "fracture/DomainIntegrals.hpp"

namespace ma::fracture {

// A point of a pressurised lip, in a parent cell the theta method reads.
struct LipPoint {
    int cell = -1;
    double weight = 0.0;
    Vec3 xyz{}, normal{};          // normal: out of the lip's material
    Vec3 u{};                      // the displacement of the point's lip
    Vec3 traction{};               // the loads' factors included
    double tractionGrad[3][3]{};   // dt_c / dx_j
    std::vector<double> N, gradN;  // the parent cell's shape functions at the point, gradN[a * 3 + j]
    double E = 0.0, nu = 0.0;      // the parent cell's material
};

// True where theta is not zero at some node of the cell: the lip term's cells (grad t . theta
// works where theta is constant too, for a function pressure).
bool thetaReaches(const Mesh& mesh, int cell, const std::vector<Vec3>& theta);

// The points of every PRES_REP FISSURE on `crack` among `loads` at instant `inst`, on the lips of
// the cells where read(cell); `u` in the numbering of `space` (whose description covers those cells).
std::vector<LipPoint> lipPoints(const Discretisation& space, const std::vector<double>& u,
                                const std::vector<LoadCase>& loads, const Concept& crack, double inst,
                                const std::function<bool(int)>& read);

// The lip term for the nodal field `theta`, the auxiliary fields in `frames[p]` at point p (or one
// frame for all when frames.size() == 1); `dim` = 2 or 3.
FrontValues lipIntegrals(const Mesh& mesh, const std::vector<LipPoint>& points, const std::vector<Vec3>& theta,
                         std::span<const FrontFrame> frames, Modelisation modelisation, int dim, bool withK);

// total += lip (G, K, G_IRWIN's components); G_IRWIN recomputed with the last lip point's material.
void addLipTerm(FrontValues& total, const FrontValues& lip, const std::vector<LipPoint>& points,
                Modelisation modelisation);

}  // namespace ma::fracture
