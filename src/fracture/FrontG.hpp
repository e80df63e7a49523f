#pragma once
// CALC_G along a 3D crack front: one theta field per front point (LISSAGE_THETA='LAGRANGE') or per
// Legendre polynomial (LISSAGE_THETA='LEGENDRE', degrees 0 ... DEGRE; FrontTheta), their domain integrals over the X-FEM elements (tip elements' quadrature included)
// with the auxiliary fields in each point's BASLOC frame, smoothed into pointwise values by
// LISSAGE_G (FrontSmoothing). docs/cracks.md.
#include <optional>
#include <utility>
#include <vector>

#include "fe/Discretisation.hpp"
#include "fracture/FrontSmoothing.hpp"
#include "fracture/FrontTheta.hpp"
#include "fracture/LipTerm.hpp"
#include "xfem/TipEnrichment.hpp"

namespace ma::fracture {

struct FrontGSetup {
    Front3D front;
    GSmoothing smoothing = GSmoothing::Lagrange;
    double rInf = 0.0, rSup = 0.0;
    std::vector<std::vector<Vec3>> thetas;               // per front point (or degree), at every mesh node
    std::vector<xfem::FrontBasis> basloc;                // at the nodes where some theta varies, and one cell beyond
    std::vector<std::array<double, 2>> basisDivergence;  // div e1, div e2 at the nodes (DomainSampling)
};

// `radii`: R_INF, R_SUP when given; otherwise 2 and 4 times the largest TAILLE_R of the front's
// points (gveri3). `degree`: LEGENDRE's DEGRE; `points`: NB_POINT_FOND (0: the front's own).
FrontGSetup frontGSetup(const Mesh& mesh, const xfem::Crack& crack, int numeFond,
                        std::optional<std::pair<double, double>> radii, GSmoothing smoothing, int degree,
                        size_t points = 0);

// True where a cell of the mesh is read: some theta field varies on it.
bool anyThetaVaries(const Mesh& mesh, int cell, const FrontGSetup& setup);
// True where some theta is not zero at a node of the cell (the lip term's cells).
bool anyThetaReaches(const Mesh& mesh, int cell, const FrontGSetup& setup);

// The smoothed values at each front point for displacement `u` (numbering of `space`), with the
// lip-pressure term of `lips` (LipTerm; their frames: BASLOC at each point).
std::vector<FrontValues> frontValues(const Discretisation& space, const std::vector<double>& u,
                                     const xfem::Crack& crack, const FrontGSetup& setup, bool withK,
                                     const std::vector<LipPoint>& lips = {});

}  // namespace ma::fracture
