#pragma once
// The solution at the integration points of the cells where theta varies (elsewhere grad theta = 0):
// integrals of CALC_G read. The displacement gradient comes from fe's element description (every
// slot and multiplier of an X-FEM element: Heaviside sides, crack-tip functions), in one place.
#include <vector>

#include "core/Vec3.hpp"
#include "fe/Discretisation.hpp"
#include "fracture/DomainIntegrals.hpp"

namespace ma::fracture {

// Every term of the domain integrals has a factor grad theta (no lip pressure or volume force term:
// refused by CALC_G), so a cell where theta is the same at every node adds exactly nothing; the
// cells inside R_INF hold most of the crack-tip quadrature's points.
bool thetaVaries(const Mesh& mesh, int cell, const std::vector<Vec3>& theta);

// The points of the cells where theta varies (thetaVaries); `space` needs only their descriptions.
// `u` in the numbering of `space`; `theta` and `lsn` at every mesh node; `positiveLsnSide` = +1
// when LSN > 0 is the theta = +pi side of the front frame, -1 otherwise.
std::vector<DomainPoint> domainPoints(const Discretisation& space, const std::vector<double>& u,
                                      const std::vector<Vec3>& theta, const std::vector<double>& lsn,
                                      double positiveLsnSide);

}  // namespace ma::fracture
