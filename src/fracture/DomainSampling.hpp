#pragma once
// The solution at the integration points of the cells where theta varies (elsewhere grad theta = 0):
// integrals of CALC_G read. The displacement gradient comes from fe's element description (every
// slot and multiplier of an X-FEM element: Heaviside sides, crack-tip functions), in one place.
#include <array>
#include <functional>
#include <span>
#include <vector>

#include "core/Vec3.hpp"
#include "fe/Discretisation.hpp"
#include "fracture/DomainIntegrals.hpp"
#include "xfem/TipEnrichment.hpp"

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

// BASLOC at a point of a cell (`N` its shape functions at the point): the nodal origins and
// directions interpolated, e2 normalised, e1 made orthogonal to it, e3 = e1 x e2.
FrontFrame interpolatedFrame(const std::vector<xfem::FrontBasis>& basloc, std::span<const int> nodes,
                             std::span<const double> N);

// The points of several theta fields at once (a 3D front's, one per front point or degree), each
// with its frame: the nodal BASLOC `basloc` interpolated at the point, e2 normalised, e1 made
// orthogonal to it, e3 = e1 x e2 (code_aster's coor_cyl / xbasgl), its gradient and, from
// `basisDivergence` (div e1, div e2 at the nodes, basisDivergence below), grad(div e1), grad(div e2);
// LSN > 0 is the e2 side. The
// cells are read once; `sink(k, points, frames)` gets field k's points cell by cell (crack-tip cells
// hold ~10^5 points: kept, they would double the peak memory of ssnv185c). Each cell is described
// (X-FEM points, crack-tip fields with its material) when it is read: `space` gives the numbering
// and the material, and need not hold any X-FEM description.
using FieldPointSink =
    std::function<void(size_t field, const std::vector<DomainPoint>& points, const std::vector<FrontFrame>& frames)>;
void domainPoints3D(const Discretisation& space, const std::vector<double>& u,
                    const std::vector<std::vector<Vec3>>& thetas, const std::vector<double>& lsn,
                    const std::vector<xfem::FrontBasis>& basloc,
                    const std::vector<std::array<double, 2>>& basisDivergence, const FieldPointSink& sink);

// div e1 and div e2 of the normalised nodal bases at every node: at each node the average over the
// cells around it of the divergence there (as GRLNNO), nodes without a basis counting as zero.
std::vector<std::array<double, 2>> basisDivergence(const Mesh& mesh, const std::vector<xfem::FrontBasis>& basloc);

}  // namespace ma::fracture
