#pragma once
// Numbering of the unknowns of a model (nume_ddl): per node a list of slots (slot 0 = DX, DY[, DZ],
// slot k >= 1 = HkX, HkY[, HkZ], from Enrichment::nodeSlots) followed by the node's extra
// unknowns (contact multipliers LAGS_C ... registered by the contact engine), all contiguous:
//
//   dof(node, slot, comp) = first(node) + slot * dim + comp
//   dof of extra unknown e of node = first(node) + slots(node) * dim + (position of e in the node's list)
//
// The crack-tip unknowns K1, K2[, K3] of the nodes the enrichment says (Enrichment::tipNode) are
// extra unknowns of those nodes, after the ones given by the caller.
//
// Only nodes of the model's elements (volume and skin) carry unknowns.
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "fe/Model.hpp"
#include "fields/Fields.hpp"

namespace ma {

// Unknowns beyond the displacement slots, per node (e.g. {"LAGS_C"} on contact nodes).
struct ExtraUnknowns {
    std::vector<std::string> names;           // global list, in output order
    std::map<int, std::vector<int>> perNode;  // node -> indices into names
};

class DofNumbering {
public:
    explicit DofNumbering(const Model& model, const ExtraUnknowns& extra = {});

    int size() const { return first_.back(); }
    int dim() const { return dim_; }
    int nodeCount() const { return static_cast<int>(slots_.size()); }
    bool hasNode(int node) const { return first_[node + 1] > first_[node]; }
    int slots(int node) const { return slots_[node]; }
    int first(int node) const { return first_[node]; }
    int maxSlots() const { return maxSlots_; }
    // -1 when the node does not carry it.
    int dof(int node, int slot, int comp) const {
        return slot < slots_[node] && comp < dim_ ? first_[node] + slot * dim_ + comp : -1;
    }
    // Crack-tip unknown K(comp+1) of a node, -1 when the node has none.
    int tipDof(int node, int comp) const {
        return tipFirst_.empty() || tipFirst_[size_t(node)] < 0 || comp >= dim_ ? -1 : tipFirst_[size_t(node)] + comp;
    }
    int tipNodeCount() const { return tipNodes_; }
    // "DX", "H2Y", "LAGS_C", "K1" ...; -1 when the node does not carry it. UserError for a name that is no
    // component of DEPL_R at all.
    int dofOf(int node, const std::string& component) const;
    // Node and component name of a dof (for messages).
    int nodeOf(int dof) const;
    std::string componentOf(int dof) const;

    // Component names of the NodalField (DX, DY[, DZ], H1X ... up to the largest slot, extras).
    const std::vector<std::string>& componentNames() const { return componentNames_; }
    std::shared_ptr<NodalField> toNodalField(std::span<const double> u, const std::shared_ptr<const Mesh>& mesh) const;
    // Values of a nodal field into dof order (components the field lacks stay 0).
    std::vector<double> fromNodalField(const NodalField& field) const;

private:
    void addTipUnknowns(const Model& model);

    int dim_ = 2, maxSlots_ = 1;
    std::vector<int> first_;  // nodeCount + 1 offsets
    std::vector<int> slots_;
    ExtraUnknowns extra_;
    std::vector<int> tipFirst_;  // first crack-tip dof per node, -1 (empty: no tip node)
    int tipNodes_ = 0;
    std::vector<std::string> componentNames_;
};

// Name of component `comp` of slot `slot`: "DX", "H1Y" ...
std::string displacementComponentName(int slot, int comp);
// Parses "DX"/"H3Z": false when `name` is not a displacement component.
bool parseDisplacementComponent(const std::string& name, int& slot, int& comp);

}  // namespace ma
