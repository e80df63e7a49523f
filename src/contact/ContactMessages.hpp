#pragma once
// The contact's alarms: DEFI_CONTACT's integration, the contact facets (docs/messages.md).
#include <string>

#include "core/Message.hpp"

namespace ma {

// The zones with their facets replaced, the traces' degree, the zone's rule, the ORDRE_INT used,
// the facet type (SE2, TR3) and its Gauss family.
inline constexpr Message<std::string, int, std::string, int, std::string, std::string> CONTACT_INTEGRATION_DEGREE{
    "CONTACT_INTEGRATION",
    "contact zone(s) {}: the traces of the shape functions of the QUAD4/HEXA8 cells on these facets have degree "
    "{}, above the degree that {} integrates exactly; with it even a solution the elements represent exactly (a "
    "uniform stress per block) would only be approximated (ssnv511g with the vertex rule: relative energy error "
    "5.8e-4). miniaster integrates these facets with INTEGRATION='GAUSS', ORDRE_INT={} ({} {}) instead, which is "
    "exact for them; the other facets keep the zone's rule."};
// The zone, its rule, its facets, the rule used instead.
inline constexpr Message<std::string, std::string, int, std::string> CONTACT_INTEGRATION_NEGATIVE_WEIGHT{
    "CONTACT_INTEGRATION",
    "contact zone {}: {} has a negative weight; a contact point of negative weight turns its term concave in the "
    "point's contact pressure and the contact stabilisation indefinite (measured on ssnv513g: a negative pivot and "
    "contact statuses cycling without end). miniaster integrates the zone's {} facets with {} instead (positive "
    "weights, at least the same degree)."};
// The faces, "total length" (2D) or "total area" (3D), their measure, their fraction of the interfaces.
inline constexpr Message<int, std::string, double, double> CONTACT_SLIVER{
    "CONTACT_SLIVER",
    "{} sub-cell face(s) on the contact interfaces ({} {:.3e}, {:.1e} of the interfaces) have no sub-cell of the "
    "other side: the two sides of the interface are cut differently there (next to a junction, or where the "
    "interfaces pass within round-off of the nodes) and no overlap of their faces was found. No contact term is "
    "written there, so the answer can lose precision (relative errors of 1 to 100 times that fraction measured, "
    "docs/study/stability.md). Moving the interfaces or the mesh by a fraction of a cell avoids it."};

inline constexpr MessageText contactMessages[] = {
    entry(CONTACT_INTEGRATION_DEGREE),
    entry(CONTACT_INTEGRATION_NEGATIVE_WEIGHT),
    entry(CONTACT_SLIVER),
};

}  // namespace ma
