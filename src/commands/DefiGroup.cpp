// DEFI_GROUP (commands_spec §8.1): groups of cells and nodes added to a mesh (reuse). DETR_GROUP_*
// are done first, then every CREA_GROUP_MA occurrence in order, then every CREA_GROUP_NO, so that
// later occurrences can use the groups of earlier ones.
#include <fmt/format.h>

#include "commands/DefiGroupOptions.hpp"
#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "mesh/GroupSelection.hpp"
#include "mesh/MeshMessages.hpp"
#include "parser/CommandRegistry.hpp"

namespace ma {
namespace {

const std::vector<int>& groupOf(const GroupSet& groups, const std::string& name, const KeywordSet& occ,
                                const std::string& keyword, const Mesh& mesh) {
    return namedGroup(mesh, &groups == &mesh.cellGroups ? GroupKind::Cells : GroupKind::Nodes, name,
                      occ.pathOf(keyword));
}

std::vector<const std::vector<int>*> groupLists(const GroupSet& groups, const KeywordSet& occ,
                                                const std::string& keyword, const Mesh& mesh) {
    std::vector<const std::vector<int>*> lists;
    for (const auto& name : occ.texts(keyword)) lists.push_back(&groupOf(groups, name, occ, keyword, mesh));
    return lists;
}

// Set operations shared by CREA_GROUP_MA and CREA_GROUP_NO; false when none is present.
bool setOperation(const GroupSet& groups, const KeywordSet& occ, const Mesh& mesh, std::vector<int>& out) {
    if (occ.has("INTERSEC")) out = intersectionOf(groupLists(groups, occ, "INTERSEC", mesh));
    else if (occ.has("UNION")) out = unionOf(groupLists(groups, occ, "UNION", mesh));
    else if (occ.has("DIFFE")) out = differenceOf(groupLists(groups, occ, "DIFFE", mesh));
    else return false;
    return true;
}

void store(Mesh& mesh, GroupSet& groups, const std::string& name, std::vector<int> members, const KeywordSet& occ,
           bool alarms, const char* kind) {
    if (groups.has(name))
        throw UserError(fmt::format("{}: the {} group '{}' already exists in mesh {}", occ.pathOf("NOM"), kind, name,
                                    mesh.name.empty() ? "(unnamed)" : mesh.name));
    if (name.empty() || name.size() > 24)
        throw UserError(fmt::format("{}: group name '{}' must have 1 to 24 characters", occ.pathOf("NOM"), name));
    if (members.empty()) {
        if (alarms) msg().alarm(SOUSTRUC_36, occ.path(), kind, name);
        return;
    }
    msg().infof("    {} group {:<24} created: {} {}", kind, name, members.size(),
                std::string(kind) == "cell" ? "cells" : "nodes");
    groups.set(name, std::move(members));
}

void createCellGroup(Mesh& mesh, const KeywordSet& occ, bool alarms) {
    const std::string name = occ.text("NOM");
    std::vector<int> cells;
    if (setOperation(mesh.cellGroups, occ, mesh, cells)) {
    } else if (occ.has("TOUT")) {
        for (int c = 0; c < mesh.cellCount(); ++c) cells.push_back(c);
    } else if (occ.has("GROUP_MA")) {
        cells = unionOf(groupLists(mesh.cellGroups, occ, "GROUP_MA", mesh));
    } else if (occ.has("MAILLE")) {
        for (const auto& n : occ.texts("MAILLE")) {
            const int c = mesh.findCell(n);
            if (c < 0) throw UserError(fmt::format("{}: cell '{}' does not exist", occ.pathOf("MAILLE"), n));
            cells.push_back(c);
        }
    } else if (occ.has("OPTION")) {
        cells = defi_group::cellOption(mesh, occ);
    } else {
        throw UserError(occ.path() + ": give TOUT, GROUP_MA, MAILLE, INTERSEC, UNION, DIFFE or OPTION");
    }
    cells = filterCellType(mesh, cells, occ.text("TYPE_MAILLE"));
    store(mesh, mesh.cellGroups, name, std::move(cells), occ, alarms, "cell");
}

NodeCriterion nodeCriterion(const KeywordSet& occ) {
    // CRIT_NOEUD (default TOUS) exists with GROUP_MA only: TOUT_GROUP_MA takes every node.
    if (!occ.has("CRIT_NOEUD")) return NodeCriterion::All;
    const std::string crit = occ.text("CRIT_NOEUD");
    if (crit == "SOMMET") return NodeCriterion::Vertices;
    if (crit == "MILIEU") return NodeCriterion::MidNodes;
    if (crit == "CENTRE") return NodeCriterion::Centres;
    return NodeCriterion::All;
}

void createNodeGroups(Mesh& mesh, const KeywordSet& occ, bool alarms) {
    std::vector<std::string> names = occ.has("NOM") ? occ.texts("NOM") : std::vector<std::string>{};
    auto single = [&]() -> std::string {
        if (names.size() != 1) throw UserError(occ.pathOf("NOM") + " expects one group name here");
        return names.front();
    };
    std::vector<int> nodes;
    if (occ.has("OPTION")) {
        // First: NOEUD_ORDO and SEGM_DROI_ORDO take GROUP_MA, GROUP_NO or NOEUD of their own.
        store(mesh, mesh.nodeGroups, single(), defi_group::nodeOption(mesh, occ), occ, alarms, "node");
    } else if (setOperation(mesh.nodeGroups, occ, mesh, nodes)) {
        store(mesh, mesh.nodeGroups, single(), std::move(nodes), occ, alarms, "node");
    } else if (occ.has("TOUT_GROUP_MA")) {
        for (const auto& g : std::vector<std::string>(mesh.cellGroups.names())) {
            if (mesh.nodeGroups.has(g)) {
                if (alarms) msg().alarm(SOUSTRUC_37, g);
                continue;
            }
            store(mesh, mesh.nodeGroups, g, nodesOfCells(mesh, mesh.cellGroups.get(g), nodeCriterion(occ)), occ, alarms,
                  "node");
        }
    } else if (occ.has("GROUP_MA")) {
        const auto groups = occ.texts("GROUP_MA");
        if (!names.empty() && names.size() != groups.size())
            throw UserError(fmt::format("{} gives {} names for {} groups of {}", occ.pathOf("NOM"), names.size(),
                                        groups.size(), occ.pathOf("GROUP_MA")));
        for (size_t i = 0; i < groups.size(); ++i) {
            const auto& cells = groupOf(mesh.cellGroups, groups[i], occ, "GROUP_MA", mesh);
            store(mesh, mesh.nodeGroups, names.empty() ? groups[i] : names[i],
                  nodesOfCells(mesh, cells, nodeCriterion(occ)), occ, alarms, "node");
        }
    } else if (occ.has("GROUP_NO")) {
        store(mesh, mesh.nodeGroups, single(), unionOf(groupLists(mesh.nodeGroups, occ, "GROUP_NO", mesh)), occ, alarms,
              "node");
    } else if (occ.has("NOEUD")) {
        for (const auto& n : occ.texts("NOEUD")) {
            const int i = mesh.findNode(n);
            if (i < 0) throw UserError(fmt::format("{}: node '{}' does not exist", occ.pathOf("NOEUD"), n));
            nodes.push_back(i);
        }
        store(mesh, mesh.nodeGroups, single(), std::move(nodes), occ, alarms, "node");
    } else {
        throw UserError(occ.path() +
                        ": give TOUT_GROUP_MA, GROUP_MA, GROUP_NO, NOEUD, INTERSEC, UNION, DIFFE or OPTION");
    }
}

ConceptPtr defiGroup(const KeywordSet& kw, CommandContext& ctx) {
    auto mesh = kw.object<Mesh>("MAILLAGE");
    if (ctx.reused && ctx.reused != mesh) throw UserError("DEFI_GROUP: reuse= must name the mesh given by MAILLAGE");
    const bool alarms = kw.text("ALARME") == "OUI";
    auto destroy = [&](const char* keyword, GroupSet& groups, const char* kind) {
        for (const auto& occ : kw.factor(keyword))
            for (const auto& name : occ.texts("NOM")) {
                if (groups.has(name)) {
                    groups.remove(name);
                    msg().infof("    {} group {} destroyed", kind, name);
                } else if (alarms) {
                    msg().alarm(SOUSTRUC_38, occ.pathOf("NOM"), kind, name);
                }
            }
    };
    destroy("DETR_GROUP_MA", mesh->cellGroups, "cell");
    destroy("DETR_GROUP_NO", mesh->nodeGroups, "node");
    for (const auto& occ : kw.factor("CREA_GROUP_MA")) createCellGroup(*mesh, occ, alarms);
    for (const auto& occ : kw.factor("CREA_GROUP_NO")) createNodeGroups(*mesh, occ, alarms);
    return mesh;
}

MA_REGISTER_COMMAND("DEFI_GROUP", defiGroup);

}  // namespace
}  // namespace ma
