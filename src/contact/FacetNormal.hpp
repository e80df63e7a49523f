#pragma once
// The normal of the contact terms at a point of a facet (docs/contact.md, "Formulation"): the
// normal of the discrete interface itself, so that a state the elements represent exactly (a
// uniform stress, the same on both sides, whatever the interface's shape) solves the discrete
// equations exactly.
#include <vector>

#include "contact/ContactFacets.hpp"
#include "core/Vec3.hpp"
#include "xfem/CellCut.hpp"

namespace ma::contact {

// Unit normal from the - side to the + side at a point of the - side's parent cell (`cut`, the
// physical shape-function gradients `gradN` at the point, nodeCount x 3): the gradient of the
// linear interpolant of the facet's level set over the sub-cell `subcell` (in the parent's
// reference coordinates), mapped to the physical cell at the point. Its zero set is the facet,
// so the normal is the facet's own in reference coordinates; the linear interpolant also
// reproduces a level set linear there exactly, so a vertex merged onto a node near a straight
// interface does not tilt it. The level set's gradient in the cell when the sub-cell is
// degenerate, the facet's geometric normal when both vanish.
Vec3 facetNormal(const xfem::CellCut& cut, const ContactFacet& facet, int subcell, int nodeCount,
                 const std::vector<double>& gradN);

}  // namespace ma::contact
