#pragma once
// ZONE/INTEGRATION and ORDRE_INT of DEFI_CONTACT (FORMULATION='XFEM'): the integration rule of the
// contact facets of a zone, chosen as code_aster chooses it (docs/contact.md, "Integration of the
// contact terms"): bibfor/elements/xminte.F90 maps the scheme and its order to an integration
// family of the facet element (SE2 in 2D, TR3 in 3D), whose points are those of elraga.F90.
#include <array>
#include <string>
#include <vector>

#include "mesh/CellType.hpp"

namespace ma {
struct QuadratureRule;
}

namespace ma::contact {

struct ContactIntegration {
    std::string scheme = "GAUSS";  // INTEGRATION: 'NOEUD', 'GAUSS', 'SIMPSON' or 'NCOTES'
    int order = 6;                 // ORDRE_INT (unused with 'NOEUD')
};

// code_aster's facet family for the scheme ("NOEU", "FPG4", "SIMP1", ...) in dimension 2 or 3, or
// an empty string where code_aster defines no rule (3D: SIMPSON of order 2..4 -> SIMP1 and NCOTES ->
// COTES exist for SE2 only; NCOTES of order 6..8 selects no family at all).
std::string facetFamily(int dim, const ContactIntegration& integration);

// Why there is no facet rule for the scheme (empty when facetFamily has one), for the error message.
std::string missingRuleReason(int dim, const ContactIntegration& integration);

// Degree, along a facet, of the parent cell's shape functions restricted to it (the traces the
// contact terms integrate; refVertices: the facet vertices in the parent's reference coordinates):
// 1 in simplices; in QUAD4/HEXA8 the number of reference coordinates that vary over the facet (2D: 1
// along a grid line xi or eta = const, else 2; 3D: 2 in a plane xi_k = const, else 3).
int facetTraceDegree(CellType parent, const std::vector<std::array<double, 3>>& refVertices);

// Whether every weight of the rule is positive. A contact point of negative weight turns its
// contact term concave in the point's pressure and the stabilisation gamma sum w g(v)^2 indefinite
// (TR3 FPG4, centre weight -27/96: ssnv513g's active set cycled, MUMPS negative pivot; docs/contact.md).
bool positiveWeights(const QuadratureRule& rule);

// Smallest ORDRE_INT of INTEGRATION='GAUSS' whose facet rule is exact for that degree and has
// positive weights only (3D degree 3: ORDRE_INT=4, TR3 FPG6, not FPG4).
int gaussOrderFor(int dim, int degree);

// For the .mess: "INTEGRATION='NOEUD' (facet vertices)", "INTEGRATION='GAUSS', ORDRE_INT=6 (SE2 FPG4)".
std::string describe(int dim, const ContactIntegration& integration);

}  // namespace ma::contact
