#pragma once
// The interface through which an X-FEM model (src/xfem) changes what the classical engine does:
// more unknowns per node, sub-cell integration of cut elements, and what DDL_IMPO means on
// enriched nodes. The engine (src/fe) knows
// only this interface, so fe does not depend on xfem.
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "fe/DirichletRelation.hpp"
#include "fe/ElementIntegration.hpp"

namespace ma {

class Model;    // fe/Model.hpp
class Concept;  // core/Concept.hpp

// The points of one side of an interface inside one parent cell, for loads on the lips
// (PRES_REP FISSURE): the faces of that side's integration sub-cells that lie on the interface.
struct LipIntegration {
    // Parent cell, points in its reference element, the node slots and psi of that side; the
    // physical weights are `weight` (refWeights unused). Crack-tip nodes are flagged (element.tip)
    // without the fields: tipFields gives Phi for the material of the load's user.
    ElementIntegration element;
    std::vector<std::array<double, 3>> xyz;     // physical points
    std::vector<double> weight;                 // physical weights (length or area of the faces)
    std::vector<std::array<double, 3>> normal;  // unit, out of this side's material (towards the other lip)
};

class Enrichment {
public:
    virtual ~Enrichment() = default;
    // 1 + number of Heaviside slots carried by `node` (1 for a node that is not enriched).
    virtual int nodeSlots(int node) const = 0;
    // True when `node` carries the crack-tip unknowns K1, K2[, K3] (ElementIntegration::tip).
    virtual bool tipNode(int /*node*/) const { return false; }
    // True when the element on `cell` is an X-FEM element (integrated on sub-cells).
    virtual bool isEnriched(int cell) const = 0;
    // Integration description of an enriched element (volume or skin cell).
    virtual void integration(int cell, ElementIntegration& out) const = 0;
    // The material's crack-tip fields (ei.tipPhi, as applyTipLaw gives them; tipA, tipB left empty)
    // at the points of `ei`, the description `integration` gave for `cell` (refPoints, pointSubcell,
    // tip flags): a Discretisation keeps the description without them and fills them again each
    // time it hands the element out.
    virtual void tipFields(int /*cell*/, const TipLaw& /*law*/, ElementIntegration& /*ei*/) const {}
    // Parent local nodes that are vertices of each integration sub-cell of an enriched `cell`, in
    // sub-cell order (ElementIntegration::pointSubcell); empty for a classical cell. CALC_CHAMP's
    // ELNO fields average the sub-cells around each parent node (post/NodeValues.hpp).
    virtual std::vector<std::vector<int>> subcellParentNodes(int /*cell*/) const { return {}; }
    // Smallest retained volume fraction of an enrichment support, for the log (conditioning).
    virtual double smallestRetainedFraction() const { return 1.0; }
    // Heaviside slots (node, k >= 1) that a node carries (nodeSlots) but that no element uses:
    // inactive cracks of multi-crack elements and slots dropped by the conditioning guard
    // (xfem_spec §3.9, §3.10). The engine must fix these unknowns to 0 (like DDL_IMPO = 0).
    virtual std::vector<std::pair<int, int>> inactiveSlots() const { return {}; }
    // DDL_IMPO on `model` (whose enrichment this is): appends the relations of `request` at `inst`
    // and returns true when the enrichment imposes it; false leaves the request to the load engine
    // (one-term relations on the nodes that carry the component).
    virtual bool imposeDof(const Model& /*model*/, const ImposedDof& /*request*/, double /*inst*/,
                           std::vector<LinearRelation>& /*out*/) const {
        return false;
    }
    // Loads on a boundary face whose nodes carry crack-tip unknowns: fills ei.tip, tipA, tipB at the
    // face element's points (physical positions `xyz`) with the tip fields of the volume element the
    // face bounds (the displacement on the face is that element's); returns that volume cell (whose
    // material gives Phi), or -1 when it cannot.
    virtual int boundaryTipFields(int /*cell*/, const std::vector<std::array<double, 3>>& /*xyz*/,
                                  ElementIntegration& /*ei*/) const {
        return -1;
    }
    // The lips of `crack` (a fiss_xfem of this model): appends one LipIntegration per side and
    // parent cell; false when `crack` is not an interface of this model.
    virtual bool lipIntegration(const Concept& /*crack*/, std::vector<LipIntegration>& /*out*/) const { return false; }
};

}  // namespace ma
