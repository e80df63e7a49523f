#include "mesh/Mesh.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "core/Error.hpp"

namespace ma {

const std::vector<int>& GroupSet::get(const std::string& name) const {
    auto it = members_.find(name);
    if (it == members_.end()) throw UserError("group '" + name + "' does not exist in the mesh");
    return it->second;
}

void GroupSet::set(const std::string& name, std::vector<int> members) {
    if (!has(name)) order_.push_back(name);
    members_[name] = std::move(members);
}

void GroupSet::remove(const std::string& name) {
    members_.erase(name);
    order_.erase(std::remove(order_.begin(), order_.end(), name), order_.end());
}

const std::vector<int>& namedGroup(const Mesh& mesh, GroupKind kind, const std::string& name,
                                   const std::string& keyword) {
    const GroupSet& groups = kind == GroupKind::Cells ? mesh.cellGroups : mesh.nodeGroups;
    if (!groups.has(name))
        throw UserError(fmt::format("{}: the mesh {} has no {} group '{}'", keyword,
                                    mesh.name.empty() ? "(unnamed)" : mesh.name,
                                    kind == GroupKind::Cells ? "cell" : "node", name));
    return groups.get(name);
}

int Mesh::addCell(CellType type, std::span<const int> nodes, std::string cellName) {
    int index = cellCount();
    cellTypes.push_back(type);
    connectivity.insert(connectivity.end(), nodes.begin(), nodes.end());
    cellOffsets.push_back(static_cast<int>(connectivity.size()));
    cellNames.push_back(cellName.empty() ? fmt::format("M{}", index + 1) : std::move(cellName));
    return index;
}

int Mesh::addNode(const std::array<double, 3>& xyz, std::string nodeName) {
    int index = nodeCount();
    coords.push_back(xyz);
    nodeNames.push_back(nodeName.empty() ? fmt::format("N{}", index + 1) : std::move(nodeName));
    return index;
}

int Mesh::findNode(const std::string& nodeName) const {
    if (nodeIndex_.size() != nodeNames.size()) {
        nodeIndex_.clear();
        for (int i = 0; i < static_cast<int>(nodeNames.size()); ++i) nodeIndex_.emplace(nodeNames[i], i);
    }
    auto it = nodeIndex_.find(nodeName);
    return it == nodeIndex_.end() ? -1 : it->second;
}

int Mesh::findCell(const std::string& cellName) const {
    if (cellIndex_.size() != cellNames.size()) {
        cellIndex_.clear();
        for (int i = 0; i < static_cast<int>(cellNames.size()); ++i) cellIndex_.emplace(cellNames[i], i);
    }
    auto it = cellIndex_.find(cellName);
    return it == cellIndex_.end() ? -1 : it->second;
}

int Mesh::maxCellDimension() const {
    int d = 0;
    for (auto t : cellTypes) d = std::max(d, cellDimension(t));
    return d;
}

}  // namespace ma
