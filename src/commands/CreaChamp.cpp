// CREA_CHAMP OPERATION='EXTR': a copy of a field stored in a result (commands_spec §6), chosen
// by NUME_ORDRE or by INST (CRITERE/PRECISION); NOEU, ELGA or ELNO (CALC_CHAMP's SIGM_ELNO).
#include <fmt/format.h>

#include "core/Messages.hpp"
#include "fe/Result.hpp"
#include "parser/CommandRegistry.hpp"

namespace ma {
namespace {

ConceptPtr creaChamp(const KeywordSet& kw, CommandContext&) {
    const std::string operation = kw.text("OPERATION");
    if (operation != "EXTR") throw NotImplemented("CREA_CHAMP/OPERATION='" + operation + "': only 'EXTR'");
    const std::string type = kw.text("TYPE_CHAM");
    auto result = kw.object<Result>("RESULTAT");
    const std::string field = kw.text("NOM_CHAM");
    const ResultStep* step = nullptr;
    if (kw.has("NUME_ORDRE")) {
        step = &result->step(static_cast<int>(kw.integer("NUME_ORDRE")));
    } else if (kw.has("INST")) {
        const bool relative = kw.text("CRITERE") == "RELATIF";
        step = &result->stepAtInst(kw.real("INST"), kw.real("PRECISION"), relative);
    } else {
        throw UserError("CREA_CHAMP: give NUME_ORDRE or INST");
    }
    if (type.rfind("NOEU_", 0) == 0) {
        auto f = step->nodal(field);
        if (!f)
            throw UserError(fmt::format("CREA_CHAMP: result {} has no nodal field {} at NUME_ORDRE {}", result->name,
                                        field, step->order));
        const std::string quantity = type.substr(5);  // DEPL_R
        if (f->quantity != quantity)
            throw UserError(fmt::format("CREA_CHAMP: TYPE_CHAM='{}' does not match field {} of {} (quantity {})", type,
                                        field, result->name, f->quantity));
        auto copy = std::make_shared<NodalField>(*f);
        msg().infof("    {} of {} at NUME_ORDRE {} (INST {}): {} components", field, result->name, step->order,
                    step->inst, copy->componentCount());
        return copy;
    }
    if (type.rfind("ELGA_", 0) == 0 || type.rfind("ELNO_", 0) == 0) {
        const bool atNodes = type.rfind("ELNO_", 0) == 0;
        auto f = step->gauss(field);
        if (!f || f->atNodes != atNodes)
            throw UserError(fmt::format("CREA_CHAMP: result {} has no field {} {} at NUME_ORDRE {}", result->name,
                                        field, atNodes ? "at the cells' nodes (ELNO)" : "at integration points",
                                        step->order));
        const std::string quantity = type.substr(5);  // SIEF_R
        if (f->quantity != quantity)
            throw UserError(fmt::format("CREA_CHAMP: TYPE_CHAM='{}' does not match field {} of {} (quantity {})", type,
                                        field, result->name, f->quantity));
        auto copy = std::make_shared<GaussField>(*f);
        msg().infof("    {} of {} at NUME_ORDRE {} (INST {}): {} points", field, result->name, step->order, step->inst,
                    copy->pointCount());
        return copy;
    }
    throw NotImplemented("CREA_CHAMP/TYPE_CHAM='" + type + "'");
}

MA_REGISTER_COMMAND("CREA_CHAMP", creaChamp);

}  // namespace
}  // namespace ma
