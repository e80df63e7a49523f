// AFFE_MATERIAU: a material per cell (commands_spec §8.4). MAILLAGE and/or MODELE; later AFFE
// occurrences override earlier ones on shared cells.
#include <fmt/format.h>

#include "commands/MechanicsKeywords.hpp"
#include "core/Messages.hpp"
#include "fe/Material.hpp"
#include "fe/Model.hpp"
#include "parser/CommandRegistry.hpp"

namespace ma {
namespace {

ConceptPtr affeMateriau(const KeywordSet& kw, CommandContext&) {
    auto field = std::make_shared<MaterialField>();
    std::shared_ptr<Mesh> mesh;
    if (kw.has("MODELE")) {
        auto model = kw.object<Model>("MODELE");
        field->model = model;
        mesh = model->mesh;
    }
    if (kw.has("MAILLAGE")) {
        auto m = kw.object<Mesh>("MAILLAGE");
        if (mesh && mesh != m)
            throw UserError("AFFE_MATERIAU: MAILLAGE " + m->name + " is not the mesh of MODELE " + field->model->name);
        mesh = m;
    }
    if (!mesh) throw UserError("AFFE_MATERIAU: MAILLAGE or MODELE is required");
    field->mesh = mesh;
    field->cellMaterial.assign(mesh->cellCount(), nullptr);
    for (const auto& occ : kw.factor("AFFE")) {
        const auto materials = occ.objects<Material>("MATER");
        if (materials.size() != 1)
            throw NotImplemented(fmt::format("{}: {} materials on the same cells (miniaster: one ELAS material)",
                                             occ.pathOf("MATER"), materials.size()));
        std::string what;
        const auto cells = mechanics::selectedCells(*mesh, occ, &what);
        for (int c : cells) field->cellMaterial[c] = materials[0];
        msg().infof("    {} on {} cell(s) ({})", materials[0]->name, cells.size(), what);
    }
    return field;
}

MA_REGISTER_COMMAND("AFFE_MATERIAU", affeMateriau);

}  // namespace
}  // namespace ma
