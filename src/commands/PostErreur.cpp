// POST_ERREUR: DEPL_RELA (L2 norm of the displacement error) and ENER_RELA (energy norm of the
// stress error) on groups of cells, against reference FORMULEs (commands_spec.md §5).
#include <fmt/format.h>

#include "core/Error.hpp"
#include "core/Function.hpp"
#include "core/Messages.hpp"
#include "fe/Material.hpp"
#include "fe/Model.hpp"
#include "fields/Fields.hpp"
#include "parser/CommandRegistry.hpp"
#include "post/ErrorNorms.hpp"
#include "post/PythonFormat.hpp"

namespace ma {
namespace {

ReferenceFormulas formulas(const KeywordSet& kw, const std::vector<std::string>& components) {
    ReferenceFormulas ref;
    for (const auto& c : components) {
        ref.components.push_back(c);
        std::vector<std::shared_ptr<const Function>> list;
        if (kw.has(c))
            for (const auto& f : kw.objects<Function>(c)) list.push_back(f);
        ref.formulas.push_back(std::move(list));
    }
    return ref;
}

ConceptPtr postErreur(const KeywordSet& kw, CommandContext&) {
    const std::string option = kw.text("OPTION");
    auto model = kw.object<Model>("MODELE");
    if (!model->mesh) throw UserError("MODELE " + model->name + " has no mesh");
    const auto groups = kw.texts("GROUP_MA");
    std::shared_ptr<Table> table;
    if (option == "DEPL_RELA") {
        auto field = std::dynamic_pointer_cast<NodalField>(kw.rawObject("CHAM_GD"));
        if (!field) throw UserError(kw.pathOf("CHAM_GD") + ": a nodal displacement field (NOEU_DEPL_R) is expected");
        // DX, DY[, DZ] in this order: a component without formula is zero (§5.2).
        std::vector<std::string> comps{"DX", "DY", "DZ"};
        if (model->dim == 2 && !kw.has("DZ")) comps.pop_back();
        std::shared_ptr<const MaterialField> material;
        if (kw.has("CHAM_MATER")) material = kw.object<MaterialField>("CHAM_MATER");
        table = displacementErrorTable(*model, *field, groups, formulas(kw, comps), material.get());
    } else if (option == "ENER_RELA") {
        auto field = std::dynamic_pointer_cast<GaussField>(kw.rawObject("CHAM_GD"));
        if (!field)
            throw UserError(kw.pathOf("CHAM_GD") + ": a stress field at Gauss points (ELGA_SIEF_R) is expected");
        const std::string deformation = kw.text("DEFORMATION");
        if (deformation != "PETIT")
            throw NotImplemented(kw.pathOf("DEFORMATION") + ": only DEFORMATION='PETIT' is supported");
        auto material = kw.object<MaterialField>("CHAM_MATER");
        table = energyErrorTable(*model, *field, *material, groups,
                                 formulas(kw, {"SIXX", "SIYY", "SIZZ", "SIXY", "SIXZ", "SIYZ"}));
    } else {
        throw NotImplemented(kw.pathOf("OPTION") + ": OPTION='" + option +
                             "' is not supported by miniaster (DEPL_RELA, ENER_RELA are)");
    }
    const size_t total = table->rowCount() - 1;
    msg().infof("    {}: TOTAL REFERENCE = {}, DIFFERENCE = {}{}", table->title.front(),
                pythonRepr(std::get<double>(table->cell(total, 2))),
                pythonRepr(std::get<double>(table->cell(total, 1))),
                table->columnCount() > 3 ? ", ERREUR RELATIVE = " + pythonRepr(std::get<double>(table->cell(total, 3)))
                                         : std::string(" (reference zero: no relative error)"));
    return table;
}

MA_REGISTER_COMMAND("POST_ERREUR", postErreur);

}  // namespace
}  // namespace ma
