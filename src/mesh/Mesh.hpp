#pragma once
// The mesh concept (maillage_sdaster): nodes, cells in code_aster numbering, node and cell groups.
#include <array>
#include <map>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/Concept.hpp"
#include "mesh/CellType.hpp"

namespace ma {

// Named groups in creation order (code_aster prints and writes them in that order).
class GroupSet {
public:
    bool has(const std::string& name) const { return members_.count(name) > 0; }
    // UserError naming the group when it does not exist.
    const std::vector<int>& get(const std::string& name) const;
    // Creates or replaces a group.
    void set(const std::string& name, std::vector<int> members);
    void remove(const std::string& name);
    const std::vector<std::string>& names() const { return order_; }
    size_t size() const { return order_.size(); }

private:
    std::vector<std::string> order_;
    std::map<std::string, std::vector<int>> members_;
};

class Mesh : public Concept {
public:
    std::string typeName() const override { return "maillage_sdaster"; }

    int dim = 3;  // space dimension: 2 (x, y) or 3; coordinates always hold z (0 in 2D)
    std::vector<std::array<double, 3>> coords;
    std::vector<std::string> nodeNames;

    std::vector<CellType> cellTypes;
    std::vector<int> cellOffsets{0};  // cell c has nodes connectivity[cellOffsets[c] .. cellOffsets[c+1])
    std::vector<int> connectivity;    // 0-based node indices, code_aster node order
    std::vector<std::string> cellNames;

    GroupSet nodeGroups;  // GROUP_NO
    GroupSet cellGroups;  // GROUP_MA

    int nodeCount() const { return static_cast<int>(coords.size()); }
    int cellCount() const { return static_cast<int>(cellTypes.size()); }
    std::span<const int> cellNodes(int cell) const {
        return {connectivity.data() + cellOffsets[cell],
                static_cast<size_t>(cellOffsets[cell + 1] - cellOffsets[cell])};
    }
    // Appends a cell and returns its index; name defaults to "M<index+1>".
    int addCell(CellType type, std::span<const int> nodes, std::string cellName = {});
    int addNode(const std::array<double, 3>& xyz, std::string nodeName = {});

    // Name lookup (-1 when absent); the index is rebuilt when the mesh grows.
    int findNode(const std::string& nodeName) const;
    int findCell(const std::string& cellName) const;

    // Highest topological dimension among the cells (2 for a 2D model's mesh, 3 for volumes).
    int maxCellDimension() const;

private:
    mutable std::unordered_map<std::string, int> nodeIndex_, cellIndex_;
};

// The members of the cell group (GROUP_MA) or node group (GROUP_NO) `name` that a command names
// under `keyword` (its path, e.g. "AFFE[1]/GROUP_MA"). A name the mesh does not hold is a
// UserError "<keyword>: the mesh M has no cell group 'G'", as code_aster refuses it (MODELISA7:
// "le GROUP_MA G ne fait pas partie du maillage M").
enum class GroupKind { Cells, Nodes };
const std::vector<int>& namedGroup(const Mesh& mesh, GroupKind kind, const std::string& name,
                                   const std::string& keyword);

}  // namespace ma
