#include "mesh/MeshSummary.hpp"

#include <fmt/format.h>

#include <map>

namespace ma {

std::string meshSummary(const Mesh& mesh, const std::string& meshName) {
    std::string s = fmt::format("------------ MAILLAGE {:<8} - IMPRESSIONS NIVEAU  1 ------------\n\n", meshName);
    s += fmt::format("{:<34}{:>10}\n\n", "NOMBRE DE NOEUDS", mesh.nodeCount());
    s += fmt::format("{:<34}{:>10}\n", "NOMBRE DE MAILLES", mesh.cellCount());
    std::map<int, int> perType;
    for (auto t : mesh.cellTypes) ++perType[int(t)];
    for (const auto& [code, n] : perType) s += fmt::format("{:30}{:<14}{:>10}\n", "", cellTypeName(CellType(code)), n);
    auto groups = [&](const GroupSet& set, const char* title) {
        if (set.size() == 0) return;
        s += fmt::format("\n{:<34}{:>10}\n", title, set.size());
        for (const auto& name : set.names()) s += fmt::format("{:30}{:<24}{:>10}\n", "", name, set.get(name).size());
    };
    groups(mesh.nodeGroups, "NOMBRE DE GROUPES DE NOEUDS");
    groups(mesh.cellGroups, "NOMBRE DE GROUPES DE MAILLES");
    s += std::string(80, '-') + "\n";
    return s;
}

}  // namespace ma
