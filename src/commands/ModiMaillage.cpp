// MODI_MAILLAGE, ORIE_PEAU_2D / ORIE_PEAU_3D (commands_spec §8.2): skin cells turned so that their
// normal points out of the material (reuse of the mesh).
#include <fmt/format.h>

#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "mesh/GroupSelection.hpp"
#include "mesh/SkinOrientation.hpp"
#include "parser/CommandRegistry.hpp"

namespace ma {
namespace {

std::vector<int> cellsOfGroups(const Mesh& mesh, const KeywordSet& occ, const std::string& keyword) {
    std::vector<const std::vector<int>*> lists;
    for (const auto& name : occ.texts(keyword)) {
        lists.push_back(&namedGroup(mesh, GroupKind::Cells, name, occ.pathOf(keyword)));
    }
    return unionOf(lists);
}

ConceptPtr modiMaillage(const KeywordSet& kw, CommandContext& ctx) {
    auto mesh = kw.object<Mesh>("MAILLAGE");
    if (ctx.reused && ctx.reused != mesh) throw UserError("MODI_MAILLAGE: reuse= must name the mesh given by MAILLAGE");
    auto orient = [&](const char* keyword, const char* bodyKeyword, int bodyDim) {
        for (const auto& occ : kw.factor(keyword)) {
            const auto skin = cellsOfGroups(*mesh, occ, "GROUP_MA");
            const auto bodies = occ.has(bodyKeyword) ? cellsOfGroups(*mesh, occ, bodyKeyword) : std::vector<int>{};
            if (occ.has(bodyKeyword) && bodies.empty())
                throw UserError(occ.pathOf(bodyKeyword) + ": the groups are empty");
            const auto report = orientSkin(*mesh, skin, bodies, bodyDim);
            msg().infof("    {}: {} skin cells checked, NOMBRE DE MAILLES REORIENTEES : {}", occ.path(), report.checked,
                        report.reoriented);
        }
    };
    orient("ORIE_PEAU_2D", "GROUP_MA_SURF", 2);
    orient("ORIE_PEAU_3D", "GROUP_MA_VOLU", 3);
    return mesh;
}

MA_REGISTER_COMMAND("MODI_MAILLAGE", modiMaillage);

}  // namespace
}  // namespace ma
