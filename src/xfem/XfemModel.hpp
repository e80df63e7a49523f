#pragma once
// The X-FEM enrichment of a model (MODI_MODELE_XFEM, xfem_spec §3): which cells are X-FEM
// elements, their sub-cells, the Heaviside slots of every node and the enrichment functions.
//
// Enrichment functions (§3.7). A "domain" is the tuple of Heaviside values (-1, +1, or 0 on the
// forbidden side of a branch) of a sub-cell, restricted to the cracks active at a node. A node's
// own domain follows the nodal rule of §2.5 (LSN >= 0 counts as +). Each other domain D met in
// the node's support gets one Heaviside slot k with
//     psi_k(x) = value_k  if x lies in a sub-cell of domain D, 0 elsewhere,
// value_k = 2 for nodes with several slots (2 * indicator, code_aster's multi-Heaviside nodes) and
// value_k = H(x) - H(x_node) = +-2 for a node with one crack and one slot (code_aster's shifted
// Heaviside: +2 on the + side for a node on the - side, -2 on the - side for a node on the +
// side). The displacement u = sum_a N_a (U_a0 + sum_k psi_ak U_ak) then holds one independent
// copy per domain: four rigid blocks around a double junction are represented exactly.
#include <algorithm>
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "fe/Enrichment.hpp"
#include "fe/Model.hpp"
#include "xfem/CellCut.hpp"
#include "xfem/Crack.hpp"
#include "xfem/SubcellQuadrature.hpp"
#include "xfem/TipEnrichment.hpp"

namespace ma::xfem {

enum class XfemContact { None, Standard };  // CONTACT='SANS' / 'STANDARD' (legacy 'P1P1', 'OUI')

// Enrichment state of one node that at least one X-FEM cell contains.
struct NodeEnrichment {
    std::vector<int> activeCracks;                     // model crack indices with status 1, model order
    std::vector<signed char> own;                      // own domain digits (one per active crack)
    std::vector<std::vector<signed char>> slotDomain;  // domain of each active slot (k = 1..)
    std::vector<double> slotValue;                     // psi value of each active slot in its domain
    std::vector<double> slotFraction;                  // retained support fraction (conditioning, §3.10)
    int carried = 0;                                   // Heaviside slots the node carries (active + inactive)
    int domainsBeforeGuard = 0;                        // other domains found in the support
    bool ownMissing = false;                           // own domain absent from the support (first one used)
};

class XfemModel : public Enrichment {
public:
    // Builds the enrichment of `model` (the copy made by MODI_MODELE_XFEM) for the cracks in the
    // user's order. UserError on order violations (§2.6), more than 4 slots at a node (XFEM_40).
    // `subcellDegree`: 0 for the catalogue's sub-cell rules, 1..kMaxSubcellDegree for the expert
    // override of the volume sub-cell rules (`miniaster run --subcell-quadrature`).
    XfemModel(const Model& model, std::vector<std::shared_ptr<const Crack>> cracks,
              XfemContact contact = XfemContact::None, double conditioningCriterion = 1e-8, int subcellDegree = 0);

    // Enrichment interface (src/fe).
    int nodeSlots(int node) const override;
    bool tipNode(int node) const override { return !tipNodes_.empty() && tipNodes_[size_t(node)]; }
    bool isEnriched(int cell) const override;
    void integration(int cell, ElementIntegration& out) const override;
    std::vector<std::vector<int>> subcellParentNodes(int cell) const override;
    double smallestRetainedFraction() const override { return smallestFraction_; }

    // Heaviside slots that exist on a node but carry no function there (inactive cracks of the
    // element, §3.9, and slots dropped by the conditioning guard, §3.10): (node, slot k >= 1).
    // The engine must fix these unknowns to 0 (eliminate them like DDL_IMPO = 0).
    std::vector<std::pair<int, int>> inactiveSlots() const override;
    // DDL_IMPO of a displacement component (DX, DY, DZ, HkX ...) on this model: the relations of
    // xfemDirichlet (xfem/XfemDirichlet.hpp); other components are left to the load engine.
    bool imposeDof(const Model& model, const ImposedDof& request, double inst,
                   std::vector<LinearRelation>& out) const override;
    int boundaryTipFields(int cell, const std::vector<std::array<double, 3>>& xyz,
                          ElementIntegration& ei) const override;
    void tipFields(int cell, const TipLaw& law, ElementIntegration& ei) const override;
    // PRES_REP FISSURE: the faces of each side's sub-cells on the interface (xfem/LipFaces.cpp).
    bool lipIntegration(const Concept& crack, std::vector<LipIntegration>& out) const override;

    // Data access.
    const std::vector<std::shared_ptr<const Crack>>& cracks() const { return cracks_; }
    const Mesh& mesh() const { return *mesh_; }
    std::shared_ptr<const Mesh> meshPtr() const { return mesh_; }
    XfemContact contact() const { return contact_; }
    int dim() const { return dim_; }
    // Cut data of an X-FEM cell (nullptr for a classical cell).
    const CellCut* cut(int cell) const;
    // X-FEM cells in increasing cell number.
    const std::vector<int>& xfemCells() const { return xfemCells_; }
    // Enrichment of a node (nullptr when no active slot and no carried slot).
    const NodeEnrichment* node(int node) const;
    // Number of active Heaviside slots of a node.
    int activeSlots(int node) const;
    // psi of node slot k (>= 1) in sub-cell s of an X-FEM cell.
    double psi(int node, int k, const CellCut& cut, int subcell) const;
    // Domain digits of sub-cell s for the cracks active at a node.
    std::vector<signed char> domainKey(int node, const CellCut& cut, int subcell) const;
    // The crack a slot is attached to (FISSNO: active cracks packed first, in model order), or -1.
    int slotCrack(int node, int k) const;
    // Number of cracks an X-FEM cell sees and the Heaviside slots per node of its element type
    // (nbheav, §3.3).
    int cellHeavisideCount(int cell) const;
    // Nodal domain digit of crack `c` (model index) at a node (§2.5 nodes rule).
    signed char nodalDigit(int crack, int node) const;
    // Volume (model dimension) cell of the model containing all nodes of a skin cell, or -1.
    int adjacentVolume(int skinCell) const;
    // First volume X-FEM cell where the node is enriched (NOXFEM, §4.1), or -1.
    int referenceCell(int node) const;
    // Sub-cell Gauss rule of an X-FEM cell: "FPG12", "FPG4", "FPG15", "FPG5" (volume) or the
    // segment/face rule of a skin cell (§3.6), or the override's rule of a volume cell.
    std::string subcellRule(int cell) const;
    // What decides the rule of an X-FEM cell (dimension, skin, several interfaces).
    SubcellKind subcellKind(int cell) const;
    // 0 (catalogue rules) or the override degree.
    int subcellDegree() const { return subcellDegree_; }
    int droppedSlots() const { return droppedSlots_; }
    // X-FEM cells (volume and skin) containing a node, in increasing cell number.
    std::vector<int> cellsOfNode(int node) const;
    // The crack with a front in the mesh (crack-tip enrichment), or -1; its tip-enriched nodes.
    int tipCrack() const { return tipCrack_; }
    int tipNodeCount() const { return static_cast<int>(std::count(tipNodes_.begin(), tipNodes_.end(), 1)); }
    // 2D: the front point whose fields a tip node carries (its nearest); -1 in 3D or for other nodes.
    int tipFrontOf(int node) const {
        return dim_ == 2 && tipNode(node) && !nodeFront_.empty() ? nodeFront_[size_t(node)] : -1;
    }
    // The crack-tip matrices Phi[a][c * 3 + m] of the tip nodes a (local) at reference point `ref` of
    // sub-cell `subcell` of an X-FEM cell, for Hooke coefficients (lambdaEff, mu); a skin cell's point
    // is evaluated in the volume element it bounds (2D). `cell`, `ref`: where Phi was evaluated (its
    // node a multiplies Phi[a]; zero for other nodes). False when no node there carries the tip
    // unknowns (POST_CHAM_XFEM's displacement at new nodes).
    struct TipPoint {
        int cell = -1;
        std::array<double, 3> ref{};
        double Phi[8][9] = {};
    };
    bool tipMatrix(int cell, int subcell, const std::array<double, 3>& ref, double lambdaEff, double mu,
                   TipPoint& out) const;
    // The same at a point of a volume cell on the given side of the crack (+1, -1), whatever its
    // sub-cell (POST_K1_K2_K3: the jump of the tip terms across the lips, code_aster's pjxfem).
    bool tipMatrixOnSide(int cell, const std::array<double, 3>& ref, int side, double lambdaEff, double mu,
                         TipPoint& out) const;
    // Gauss-Legendre points per direction of the collapsed rules of crack-tip elements (2D).
    static constexpr int kTipGaussPoints = 12;
    // 3D fanned rules (TipEnrichment's fannedTetrahedronRule): points along the two radii and the
    // angle of a face piece; sub-cells farther from the front line than kTipFanReach diameters
    // get a conical Gauss rule of n^3 points, n = kTipFarPoints + 4, + 2, + 1 while that distance is
    // below 0.5, 1, 2 diameters, kTipFarPoints beyond (measured on the exactness case, docs/cracks.md).
    static constexpr int kTipRadialPoints = 6;
    static constexpr int kTipAngularPoints = 8;
    static constexpr double kTipFanReach = 0.25;
    static constexpr int kTipFarPoints = 4;
    // Levels of splitting of the sub-triangles near the front point (TipEnrichment's tipTriangleRule).
    static constexpr int kTipRefinement = 4;

private:
    void buildTip();
    // ei.tipA, tipB; with `law`, ei.tipPhi instead (tipElementFields).
    void addTipFields(const CellCut& cut, ElementIntegration& out, const TipLaw* law = nullptr) const;
    // Points and weights of a crack-tip element's sub-cell s (2D, catalogue rules): collapsed
    // Gauss rules, fanned from the front point when the sub-cell contains it.
    void tipSubcellRule(const CellCut& cut, int s, std::vector<std::array<double, 3>>& points,
                        std::vector<double>& weights) const;
    // 3D: the fanned rule from the front line near it, else a conical Gauss rule.
    void tipSubcellRule3(const CellCut& cut, int s, std::vector<std::array<double, 3>>& points,
                         std::vector<double>& weights) const;
    void buildFrontLines(const Crack& crack);
    // Where tipElementFields takes the bases (nodal in 3D, front points in 2D).
    TipBases tipBases() const;
    void buildCells(const Model& model);
    void buildNodes();
    void supportDomains(int node, const std::vector<int>& active, std::vector<std::vector<signed char>>& keys,
                        std::vector<double>& weight, double& total, std::vector<double>& grad) const;
    std::vector<signed char> domainKeyFor(const std::vector<int>& active, const CellCut& cut, int s) const;

    std::shared_ptr<const Mesh> mesh_;
    std::vector<std::shared_ptr<const Crack>> cracks_;
    XfemContact contact_;
    double criterion_;
    int subcellDegree_ = 0;
    int dim_ = 2;
    std::vector<int> cellIndex_;  // cell -> index in cuts_ or -1
    std::vector<CellCut> cuts_;
    std::vector<int> xfemCells_;
    std::vector<int> heavisideCount_;  // per cuts_ entry
    std::vector<int> nodeIndex_;       // node -> index in nodes_ or -1
    std::vector<NodeEnrichment> nodes_;
    std::vector<int> nodeCellOffsets_, nodeCells_;  // node -> X-FEM cells (CSR)
    std::vector<int> skinVolume_;                   // per cuts_ entry: adjacent volume cell (skin only)
    double smallestFraction_ = 1.0;
    int droppedSlots_ = 0;
    int tipCrack_ = -1;
    std::vector<char> tipNodes_;                                  // per mesh node
    std::vector<FrontBasis> bases_;                               // 3D, per mesh node (tip elements' nodes)
    std::vector<std::optional<std::array<double, 3>>> tipPoint_;  // per cuts_ entry: front point (reference)
    std::vector<Vec3> frontPoints_;                               // 2D front points (physical)
    std::vector<FrontBasis> pointBases_;                          // 2D: per front point
    std::vector<int> nodeFront_;                                  // 2D, per mesh node: its front point
    // 3D, per cuts_ entry: the line of the front segment nearest the cell, in its reference
    // coordinates: its first point, its unit direction and (first component) its length.
    std::vector<std::optional<std::array<Vec3, 3>>> frontLine_;
};

}  // namespace ma::xfem
