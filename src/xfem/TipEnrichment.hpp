#pragma once
// Crack-tip enrichment (TYPE_ENRI_FOND), code_aster 15's vector form (xcalfev, xdeffk, xderfk,
// coor_cyl, xbasgl): a tip node carries K1, K2[, K3], each multiplying the Williams displacement
// field of its mode written in the local front basis at the point,
//
//   u(x) += N_a(x) P(x) [F(r, theta) - sum_b N_b(x) F(r_b, theta_b)] K_a
//
// (the fields minus their interpolation at the element's nodes, so that the enrichment vanishes at
// every node). F = sqrt(r / 2 pi) (kappa a(theta) + b(theta)) / (2 mu); r, theta are the polar
// coordinates of x in the plane (e1, e2) of node a's front point (2D) or of the interpolated nodal
// front bases (BASLOC, 3D), theta taking the sign of the point's side of the crack (the sub-cell's
// Heaviside value). docs/cracks.md.
#include <array>
#include <functional>
#include <optional>
#include <vector>

#include "core/Vec3.hpp"
#include "fe/ElementIntegration.hpp"
#include "mesh/Mesh.hpp"
#include "xfem/Crack.hpp"

namespace ma::xfem {

// The local front basis of a node (code_aster's BASLOC): its projection on the front, e1 the
// direction of propagation, e2 the crack's normal (unit).
struct FrontBasis {
    Vec3 origin{};
    Vec3 e1{}, e2{};
};

// BASLOC of the nodes flagged in `nodes` (others left zero). 2D (code_aster's xbaslo): the basis of
// the nearest front point, e2 the LSN gradient and e1 the LST gradient made orthogonal to e2, both
// the nodal averages (GRLNNO, GRLTNO) interpolated at the front point. 3D: the nearest point of
// the front polylines, e2 and e1 from the node's own GRLNNO, GRLTNO.
std::vector<FrontBasis> frontBases(const Mesh& mesh, const Crack& crack, const std::vector<char>& nodes);

// 2D: the basis of each front point, in the order of the crack's fronts; the index of the one
// nearest to x (the first of equals), which gives a node its BASLOC.
std::vector<FrontBasis> frontPointBases(const Mesh& mesh, const Crack& crack);
size_t nearestFrontPoint(const std::vector<FrontBasis>& points, const Vec3& x);

// The Williams fields split as F = (kappa A + B) / (2 mu): A[m][k], B[m][k] for mode m (0: I,
// 1: II, 2: III) and local component k (along e1, e2, e3), and their derivatives along the local
// axes x1, x2: dA[m][k][l] (code_aster's xdeffk and xderfk).
struct AsymptoticFields {
    double A[3][3] = {}, B[3][3] = {};
    double dA[3][3][2] = {}, dB[3][3][2] = {};
};
AsymptoticFields asymptoticFields(double r, double theta, int dim);

// Where the tip fields' bases come from. 3D: `nodal`, every node's BASLOC (indexed by mesh node),
// interpolated at the point: one group per element. 2D: `points`, the basis of each front point,
// and `front`, each mesh node's nearest front point (its BASLOC): a tip node's enrichment is its
// own front point's field in every element of its support, that basis taken for the point's polar
// coordinates and for every node's shifted value alike; an element has one group per distinct
// front point of its tip nodes (two where both tips of a short crack reach it).
struct TipBases {
    const std::vector<FrontBasis>* nodal = nullptr;
    const std::vector<FrontBasis>* points = nullptr;
    const std::vector<int>* front = nullptr;
};

// Fills ei.tip (from `tipNodes`, per local node), ei.tipGroup, ei.tipGroups, ei.tipA and ei.tipB at
// ei's points on `cell`; with `law`, ei.tipPhi instead (applyTipLaw's values, without keeping A and
// B). `status` is indexed by mesh node; `side[p]` is the Heaviside value (+-1) of the crack at point
// p's sub-cell.
void tipElementFields(const Mesh& mesh, int cell, int dim, const TipBases& bases,
                      const std::vector<unsigned char>& status, const std::vector<char>& tipNodes,
                      const std::vector<signed char>& side, ElementIntegration& ei, const TipLaw* law = nullptr);

// Gauss-Legendre points and weights on [0, 1] (n >= 1, Newton on the Legendre polynomial).
void gaussLegendre01(int n, std::vector<double>& x, std::vector<double>& w);

// A rule on the triangle (P0, P1, P2) collapsed at P0 (Duffy): n x n Gauss-Legendre points in
// (rho, t), x = P0 + rho ((1 - t) (P1 - P0) + t (P2 - P0)). With `singular`, rho = s^2 so that the
// r^-1/2 and r^-1 terms of the tip fields at P0 become smooth in (s, t). Appends points and
// weights (the triangle's area included, coordinates as given).
void collapsedTriangleRule(const std::array<double, 3>& P0, const std::array<double, 3>& P1,
                           const std::array<double, 3>& P2, int n, bool singular,
                           std::vector<std::array<double, 3>>& points, std::vector<double>& weights);

// The rule of one sub-triangle V (parent reference coordinates) of a 2D crack-tip element: fanned
// from the front point into singular collapsed rules when it contains it (`tipRef`, the point in
// the same coordinates); otherwise split in four, recursively (at most `levels` times), while the
// nearest front point (`tips`, physical) is closer to the piece than the piece's diameter, each
// final piece with the n x n collapsed rule. `toPhysical` maps reference to physical points.
void tipTriangleRule(const std::array<std::array<double, 3>, 3>& V, const std::optional<std::array<double, 3>>& tipRef,
                     const std::function<Vec3(const std::array<double, 3>&)>& toPhysical, const std::vector<Vec3>& tips,
                     int n, int levels, std::vector<std::array<double, 3>>& points, std::vector<double>& weights);

// A rule on the tetrahedron V (coordinates as given, e.g. a sub-cell in its parent's reference
// coordinates) fanned from the straight line through O along t (unit), the front of a 3D
// crack-tip element: in every plane normal to the line, the section is fanned from the line's
// point, so each point is x = P(y) + rho (y - P(y)) with y on a face and P(y) its projection on
// the line (signed: faces seen from the line's back count negatively). rho = s^2, and each face is
// split at the line's crossing into Duffy-collapsed triangles (radius = u^2), which makes the
// r^-1/2 and r^-1 terms of the tip fields smooth; nRadial points in rho and u, nAngular in the
// face's angle. Appends points and weights (the volume included).
void fannedTetrahedronRule(const std::array<std::array<double, 3>, 4>& V, const Vec3& O, const Vec3& t, int nRadial,
                           int nAngular, std::vector<std::array<double, 3>>& points, std::vector<double>& weights);

// Conical-product Gauss rule of n^3 points on the tetrahedron V (exact to degree 2n - 1).
void tetrahedronGaussRule(const std::array<std::array<double, 3>, 4>& V, int n,
                          std::vector<std::array<double, 3>>& points, std::vector<double>& weights);

// Reference coordinates of x for the cell (Newton on the shape functions, x inside or not).
std::array<double, 3> referenceCoordinates(const Mesh& mesh, int cell, const Vec3& x);

// Reference coordinates of x in the 2D cell (TRIA3, QUAD4) when x lies in it (1e-10 of slack).
std::optional<std::array<double, 3>> referencePointIn(const Mesh& mesh, int cell, const Vec3& x);

}  // namespace ma::xfem
