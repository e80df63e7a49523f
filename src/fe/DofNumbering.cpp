#include "fe/DofNumbering.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "core/Error.hpp"
#include "fe/Enrichment.hpp"

namespace ma {

std::string displacementComponentName(int slot, int comp) {
    const char axis = static_cast<char>('X' + comp);
    if (slot == 0) return fmt::format("D{}", axis);
    return fmt::format("H{}{}", slot, axis);
}

bool parseDisplacementComponent(const std::string& name, int& slot, int& comp) {
    if (name.size() < 2) return false;
    const char last = name.back();
    if (last < 'X' || last > 'Z') return false;
    comp = last - 'X';
    if (name.size() == 2 && name[0] == 'D') {
        slot = 0;
        return true;
    }
    if (name.size() == 3 && name[0] == 'H' && name[1] >= '1' && name[1] <= '9') {
        slot = name[1] - '0';
        return true;
    }
    return false;
}

DofNumbering::DofNumbering(const Model& model, const ExtraUnknowns& extra) : dim_(model.dim), extra_(extra) {
    const Mesh& mesh = *model.mesh;
    const int n = mesh.nodeCount();
    slots_.assign(n, 0);
    auto mark = [&](const std::vector<ModelElement>& elements) {
        for (const auto& e : elements)
            for (int node : mesh.cellNodes(e.cell)) slots_[node] = 1;
    };
    mark(model.elements);
    mark(model.skinElements);
    if (model.enrichment)
        for (int node = 0; node < n; ++node)
            if (slots_[node]) slots_[node] = std::max(1, model.enrichment->nodeSlots(node));
    addTipUnknowns(model);
    first_.assign(n + 1, 0);
    for (int node = 0; node < n; ++node) {
        int count = slots_[node] * dim_;
        if (auto it = extra_.perNode.find(node); it != extra_.perNode.end()) count += int(it->second.size());
        first_[node + 1] = first_[node] + count;
        maxSlots_ = std::max(maxSlots_, slots_[node]);
    }
    for (int s = 0; s < maxSlots_; ++s)
        for (int c = 0; c < dim_; ++c) componentNames_.push_back(displacementComponentName(s, c));
    for (const auto& e : extra_.names) componentNames_.push_back(e);
    if (tipNodes_ == 0) return;
    tipFirst_.assign(size_t(n), -1);
    const int k1 = static_cast<int>(std::find(extra_.names.begin(), extra_.names.end(), "K1") - extra_.names.begin());
    for (const auto& [node, list] : extra_.perNode)
        for (size_t i = 0; i < list.size(); ++i)
            if (list[i] == k1) tipFirst_[size_t(node)] = first_[node] + slots_[node] * dim_ + static_cast<int>(i);
}

void DofNumbering::addTipUnknowns(const Model& model) {
    if (!model.enrichment) return;
    std::vector<int> index;
    for (int node = 0; node < int(slots_.size()); ++node) {
        if (!slots_[size_t(node)] || !model.enrichment->tipNode(node)) continue;
        if (index.empty())
            for (int c = 0; c < dim_; ++c) {
                const std::string name = fmt::format("K{}", c + 1);
                if (std::find(extra_.names.begin(), extra_.names.end(), name) != extra_.names.end())
                    throw InternalError("crack-tip unknown " + name + " given twice");
                index.push_back(static_cast<int>(extra_.names.size()));
                extra_.names.push_back(name);
            }
        auto& list = extra_.perNode[node];
        list.insert(list.end(), index.begin(), index.end());
        ++tipNodes_;
    }
}

int DofNumbering::dofOf(int node, const std::string& component) const {
    int slot = 0, comp = 0;
    if (parseDisplacementComponent(component, slot, comp)) return dof(node, slot, comp);
    auto pos = std::find(extra_.names.begin(), extra_.names.end(), component);
    if (pos == extra_.names.end()) {
        static const char* known[] = {"K1",      "K2",      "K3",      "LAGS_C",  "LAGS_F1",
                                      "LAGS_F2", "LAG2_C",  "LAG2_F1", "LAG2_F2", "LAG3_C",
                                      "LAG3_F1", "LAG3_F2", "LAG4_C",  "LAG4_F1", "LAG4_F2"};
        for (const char* k : known)
            if (component == k) return -1;
        throw UserError("'" + component + "' is not a component of the displacement (DEPL_R)");
    }
    auto it = extra_.perNode.find(node);
    if (it == extra_.perNode.end()) return -1;
    const int index = static_cast<int>(pos - extra_.names.begin());
    for (size_t i = 0; i < it->second.size(); ++i)
        if (it->second[i] == index) return first_[node] + slots_[node] * dim_ + static_cast<int>(i);
    return -1;
}

int DofNumbering::nodeOf(int dof) const {
    return static_cast<int>(std::upper_bound(first_.begin(), first_.end(), dof) - first_.begin()) - 1;
}

std::string DofNumbering::componentOf(int dof) const {
    const int node = nodeOf(dof);
    const int local = dof - first_[node];
    if (local < slots_[node] * dim_) return displacementComponentName(local / dim_, local % dim_);
    return extra_.names[extra_.perNode.at(node)[local - slots_[node] * dim_]];
}

std::shared_ptr<NodalField> DofNumbering::toNodalField(std::span<const double> u,
                                                       const std::shared_ptr<const Mesh>& mesh) const {
    auto field = std::make_shared<NodalField>();
    field->resize(mesh, componentNames_);
    const int ndisp = maxSlots_ * dim_;
    for (int node = 0; node < nodeCount(); ++node) {
        if (!hasNode(node)) continue;
        const int base = first_[node];
        for (int i = 0; i < slots_[node] * dim_; ++i) field->set(node, i, u[base + i]);
        if (auto it = extra_.perNode.find(node); it != extra_.perNode.end())
            for (size_t i = 0; i < it->second.size(); ++i)
                field->set(node, ndisp + it->second[i], u[base + slots_[node] * dim_ + i]);
    }
    return field;
}

std::vector<double> DofNumbering::fromNodalField(const NodalField& field) const {
    std::vector<double> u(size(), 0.0);
    std::vector<int> index(componentNames_.size());
    for (size_t i = 0; i < componentNames_.size(); ++i) index[i] = field.componentIndex(componentNames_[i]);
    const int ndisp = maxSlots_ * dim_;
    for (int node = 0; node < nodeCount(); ++node) {
        if (!hasNode(node)) continue;
        const int base = first_[node];
        for (int i = 0; i < slots_[node] * dim_; ++i)
            if (index[i] >= 0 && field.has(node, index[i])) u[base + i] = field.at(node, index[i]);
        if (auto it = extra_.perNode.find(node); it != extra_.perNode.end())
            for (size_t i = 0; i < it->second.size(); ++i) {
                const int c = index[ndisp + it->second[i]];
                if (c >= 0 && field.has(node, c)) u[base + slots_[node] * dim_ + i] = field.at(node, c);
            }
    }
    return u;
}

}  // namespace ma
