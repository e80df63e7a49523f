#pragma once
// The level sets of DEFI_FISS_XFEM's predefined shapes (DEFI_FISS/FORM_FISS): closed forms of the
// position of a node relative to the shape's local frame (code_aster's xcatls, docs/cracks.md).
#include <string>
#include <vector>

#include "core/Vec3.hpp"
#include "mesh/Mesh.hpp"

namespace ma::xfem {

// The keywords of one FORM_FISS, as DEFI_FISS gives them (unused ones stay 0).
struct CrackShape {
    std::string form;           // ELLIPSE, RECTANGLE, CYLINDRE, ENTAILLE, DEMI_PLAN, SEGMENT, DEMI_DROITE, DROITE
    double semiMajor = 0.0;     // DEMI_GRAND_AXE, or DEMI_LONGUEUR (ENTAILLE)
    double semiMinor = 0.0;     // DEMI_PETIT_AXE
    double filletRadius = 0.0;  // RAYON_CONGE
    Vec3 centre{};              // CENTRE
    Vec3 vectX{}, vectY{};      // VECT_X, VECT_Y
    bool outside = false;       // COTE_FISS='OUT'
    Vec3 point{};               // PFON (DEMI_PLAN, DEMI_DROITE), POINT (DROITE), PFON_ORIG (SEGMENT)
    Vec3 end{};                 // PFON_EXTR (SEGMENT)
    Vec3 normal{};              // NORMALE (DEMI_PLAN)
    Vec3 tangent{};             // DTAN (DEMI_PLAN, DEMI_DROITE, DROITE)
};

struct ShapeLevelSets {
    std::vector<double> lsn, lst;  // at every mesh node; lst = -1 everywhere for an interface
};

// The nodal level sets of a shape for a crack (isCrack: TYPE_DISCONTINUITE='FISSURE') or an
// interface. UserError when the shape does not fit the discontinuity type or the mesh dimension
// (code_aster's XFEM_23), or when its vectors are null or VECT_X and VECT_Y not orthogonal.
ShapeLevelSets shapeLevelSets(const Mesh& mesh, const CrackShape& shape, bool isCrack);

// Signed distance from (x, y) to the ellipse x²/a² + y²/b² = 1 (negative inside), exact to
// round-off (the root of the foot-point equation by bisection).
double ellipseDistance(double x, double y, double a, double b);

// Signed distance from (x, y) to the rectangle |x| <= a, |y| <= b whose corners are rounded with
// radius r (negative inside): code_aster's disrec.
double roundedRectangleDistance(double x, double y, double a, double b, double r);

}  // namespace ma::xfem
