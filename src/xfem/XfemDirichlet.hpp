#pragma once
// DDL_IMPO on an X-FEM model (xfem_spec §4): what prescribing DX, DY, DZ or H1X ... means on
// enriched nodes, as linear relations sum_i c_i u(node_i, comp_i) = value for the engine.
//
// * H-components (H1X ...): a plain relation on nodes where that slot is active; skipped where
//   the node does not carry it or where it is inactive (already fixed to 0, §3.9).
// * DX/DY/DZ on a node that is not enriched, or whose first X-FEM element (NOXFEM) sees several
//   cracks: DX = value.
// * DX on an enriched node of a single-crack element:
//   - real value (§4.2): DX = value (the node's own side; psi = 0 there). For a node ON the
//     interface, the sides of the other prescribed nodes around it decide: both sides (or none)
//     -> DX = v and DX + psi_-·H1X = v (both lips, alarm XFEM_22); one side -> that side only.
//   - function (§4.3): DX = f(node) and H1X chosen so that the enriched interpolation along a cut
//     edge of the prescribed group equals f just on each side of the crossing; a node on the
//     interface gets DX = f+ and the H1X that gives f- on the - side.
#include <vector>

#include "fe/DirichletRelation.hpp"

namespace ma::xfem {

class XfemModel;

// Relations of one DDL_IMPO component (request) on an X-FEM model. Function values are evaluated
// in one batch at the nodes and at the points just on each side of the crossings.
std::vector<LinearRelation> xfemDirichlet(const XfemModel& xm, const ImposedDof& request, double inst);

}  // namespace ma::xfem
