#pragma once
// ZONE/INTEGRATION and ORDRE_INT of DEFI_CONTACT (FORMULATION='XFEM'): the integration rule of the
// contact facets of a zone, chosen as code_aster chooses it (docs/contact.md, "Integration of the
// contact terms"): bibfor/elements/xminte.F90 maps the scheme and its order to an integration
// family of the facet element (SE2 in 2D, TR3 in 3D), whose points are those of elraga.F90.
#include <array>
#include <string>
#include <vector>

#include "mesh/CellType.hpp"

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

// Smallest ORDRE_INT of INTEGRATION='GAUSS' whose facet rule is exact for that degree.
int gaussOrderFor(int dim, int traceDegree);

// For the .mess: "INTEGRATION='NOEUD' (facet vertices)", "INTEGRATION='GAUSS', ORDRE_INT=6 (SE2 FPG4)".
std::string describe(int dim, const ContactIntegration& integration);

}  // namespace ma::contact
