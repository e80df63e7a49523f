#pragma once
// X-FEM's alarms: DEFI_FISS_XFEM, MODI_MODELE_XFEM, prescribed displacements (docs/messages.md).
#include <string>

#include "core/Message.hpp"

namespace ma {

// DEFI_FISS_XFEM: the keyword path; the count of values moved.
inline constexpr Message<std::string> XFEM_25{"XFEM_25", "{} is ignored with TYPE_DISCONTINUITE='INTERFACE'"};
inline constexpr Message<int> XFEM_63{
    "XFEM_63", "{} nodal level-set values were moved onto the interface (their zero lay within 1e-6 of an edge end)"};
// DEFI_FISS_XFEM, TYPE_DISCONTINUITE='FISSURE': the crack's name.
inline constexpr Message<std::string> XFEM_58{
    "XFEM_58",
    "no point of the front of crack {} was found: the front lies outside the structure, which the crack cuts "
    "through (Heaviside enrichment only). If an interface was meant, give TYPE_DISCONTINUITE='INTERFACE'; "
    "otherwise check the tangential level set"};
inline constexpr Message<> XFEM_ENRI{
    "XFEM_ENRI",
    "the interface enriches no node (it lies on the boundary of the structure or between the cells without "
    "separating any node support)"};

// MODI_MODELE_XFEM: the sub-cell degree, the parent type, the strains' degree, the rule, the cells,
// the parent type, the strains' degree.
inline constexpr Message<int, std::string, int, std::string, int, std::string, int> XFEM_SUBCELL_RULE{
    "XFEM_SUBCELL_RULE",
    "--subcell-quadrature {}: the strains of the {} shape functions are polynomials of degree {} on the "
    "sub-cells, which the rule {} does not integrate exactly: uniform stress states are no longer reproduced on "
    "the {} X-FEM {} elements (the patch test fails, the answer carries a quadrature error). Use a degree >= {}."};

// DDL_IMPO on X-FEM nodes: the keyword path and the component first.
inline constexpr Message<std::string, std::string> XFEM_22{
    "XFEM_22",
    "{}: {} is prescribed on both lips of nodes lying on an interface; do not also prescribe their Heaviside "
    "components (singular system)"};
// The component, its value, the node.
inline constexpr Message<std::string, std::string, double, std::string> XFEM_DDL_INACTIVE_SLOT{
    "XFEM_DDL", "{}: {} = {} ignored on node {}: that Heaviside slot is inactive there and fixed to 0"};
// The node, the interface, the component.
inline constexpr Message<std::string, std::string, std::string, std::string> XFEM_DDL_INTERFACE_NODES{
    "XFEM_DDL",
    "{}: node {} lies on the interface {} and the other prescribed nodes around it too: {} is not imposed there"};

inline constexpr MessageText xfemMessages[] = {
    entry(XFEM_25),
    entry(XFEM_63),
    entry(XFEM_58),
    entry(XFEM_ENRI),
    entry(XFEM_SUBCELL_RULE),
    entry(XFEM_22),
    entry(XFEM_DDL_INACTIVE_SLOT),
    entry(XFEM_DDL_INTERFACE_NODES),
};

}  // namespace ma
