#pragma once
// The virtual crack extensions of CALC_G along a 3D crack front (code_aster's gveri3, glegen and
// gcour3 for a fiss_xfem): one field per function phi_k of the front. At a node, with d its distance
// to the nearest point of the front polyline (segment j, parameter s in [0, 1]),
//
//   theta_k = phi_k(s) g     within R_INF of the front, times (1 - alpha) in the crown,
//                            0 beyond R_SUP, alpha = (d - R_INF) / (R_SUP - R_INF),
//
// phi_k interpolated linearly on the segment from its values at the front points and g the node's
// GRLTNO (not normalised, as gcour3 takes it); on the first and the last segment g is replaced by
// the front points' propagation directions interpolated with phi_k. LISSAGE_THETA='LAGRANGE':
// phi_k the hat of front point k (a closed front, its first point repeated at the end, joins the
// hats of its first and last points); 'LEGENDRE': the Legendre polynomial of degree k on [0, L]
// normalised in L2 (sqrt((2k + 1) / L) P_k(2 s / L - 1)).
#include <vector>

#include "core/Vec3.hpp"
#include "fracture/DomainIntegrals.hpp"
#include "mesh/Mesh.hpp"
#include "xfem/Crack.hpp"

namespace ma::fracture {

struct Front3D {
    std::vector<Vec3> points;        // in order (a closed front repeats its first point)
    std::vector<double> abscissa;    // curvilinear abscissa from the first point
    std::vector<FrontFrame> frames;  // e1 propagation, e2 normal (GRLTNO, GRLNNO at the point)
    std::vector<double> cellSize;    // TAILLE_R: max over the tip cells holding the point of |edge . e1|
    bool closed = false;
};

// Front NUME_FOND (1-based) of a 3D crack; UserError when there is no such front.
Front3D front3D(const Mesh& mesh, const xfem::Crack& crack, const std::vector<Vec3>& grln,
                const std::vector<Vec3>& grlt, int numeFond);

// NB_POINT_FOND (code_aster's xrecff): `count` points evenly spaced in abscissa on the front
// polyline, the first and last kept, coordinates and frames interpolated linearly between the two
// original points around (the frames are not renormalised, as code_aster's BASEFOND); TAILLE_R
// keeps the original points' (the default crown takes their largest).
Front3D redistributed(const Front3D& front, size_t count);

// The nearest point of the front polyline to x: segment j (0-based), parameter s and distance.
struct FrontProjection {
    size_t segment = 0;
    double s = 0.0, distance = 0.0;
};
FrontProjection projectOnFront(const Front3D& front, const Vec3& x);

// phi_k at the front points: Lagrange's hat of point k, or the normalised Legendre polynomial of
// degree k at the abscissae `s` of a front of length `length`.
std::vector<double> lagrangeHat(const Front3D& front, size_t k);
std::vector<double> legendrePolynomial(const std::vector<double>& s, double length, int k);

// theta_k at every mesh node for phi_k given at the front points.
std::vector<Vec3> frontTheta(const Mesh& mesh, const Front3D& front, const std::vector<FrontProjection>& nodes,
                             const std::vector<Vec3>& grlt, const std::vector<double>& phi, double rInf, double rSup);

}  // namespace ma::fracture
