#include "mesh/MeshSummary.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>

#include "mesh/MeshMessages.hpp"

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

std::vector<FormattedMessage> meshDefects(const Mesh& mesh, const std::string& path) {
    std::vector<FormattedMessage> out;
    std::vector<char> used(size_t(mesh.nodeCount()), 0);
    for (int v : mesh.connectivity) used[size_t(v)] = 1;
    const auto orphans = std::count(used.begin(), used.end(), 0);
    if (orphans > 0) {
        int first = int(std::find(used.begin(), used.end(), 0) - used.begin());
        out.push_back(formatted(MODELISA_VERI_MAIL_ORPHAN_NODES, path, orphans, mesh.nodeNames[size_t(first)]));
    }
    int repeated = 0;
    std::string example;
    for (int c = 0; c < mesh.cellCount(); ++c) {
        const auto n = mesh.cellNodes(c);
        bool twice = false;  // pairwise: cells have at most 27 nodes
        for (size_t i = 1; i < n.size() && !twice; ++i)
            for (size_t j = 0; j < i && !twice; ++j) twice = n[i] == n[j];
        if (twice && repeated++ == 0) example = mesh.cellNames[size_t(c)];
    }
    if (repeated > 0) out.push_back(formatted(MODELISA_VERI_MAIL_REPEATED_NODE, path, repeated, example));
    return out;
}

}  // namespace ma
