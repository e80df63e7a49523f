// CREA_CHAMP OPERATION='EXTR': a copy of a field stored in a result (commands_spec §6), chosen
// by NUME_ORDRE or by INST (CRITERE/PRECISION); NOEU, ELGA or ELNO (CALC_CHAMP's SIGM_ELNO); or a
// level set of a crack (FISSURE, NOM_CHAM LNNO, LTNO, GRLNNO, GRLTNO).
#include <fmt/format.h>

#include "core/Messages.hpp"
#include "fe/Result.hpp"
#include "parser/CommandRegistry.hpp"
#include "xfem/Crack.hpp"

namespace ma {
namespace {

// A level set of a crack (LNNO, LTNO: component X1) or its nodal gradient (GRLNNO, GRLTNO: X1…Xdim),
// on the crack's mesh, as code_aster stores them in the fiss_xfem concept (NEUT_R fields).
ConceptPtr crackField(const KeywordSet& kw) {
    const std::string type = kw.text("TYPE_CHAM"), field = kw.text("NOM_CHAM");
    auto crack = kw.object<xfem::Crack>("FISSURE");
    if (type != "NOEU_NEUT_R")
        throw UserError(
            fmt::format("CREA_CHAMP: field {} of crack {} is a nodal NEUT_R field: give "
                        "TYPE_CHAM='NOEU_NEUT_R' (not '{}')",
                        field, crack->name, type));
    const Mesh& mesh = *crack->mesh;
    const bool normal = field == "LNNO" || field == "GRLNNO";
    const auto& values = normal ? crack->lsn : crack->lst;
    auto out = std::make_shared<NodalField>();
    out->quantity = "NEUT_R";
    if (field == "LNNO" || field == "LTNO") {
        out->resize(crack->mesh, {"X1"});
        for (int n = 0; n < mesh.nodeCount(); ++n) out->set(n, 0, values[size_t(n)]);
    } else {
        const int dim = mesh.dim == 3 ? 3 : 2;
        out->resize(crack->mesh,
                    dim == 3 ? std::vector<std::string>{"X1", "X2", "X3"} : std::vector<std::string>{"X1", "X2"});
        const auto gradient = xfem::nodalLevelSetGradient(mesh, values);
        for (int n = 0; n < mesh.nodeCount(); ++n)
            for (int j = 0; j < dim; ++j) out->set(n, j, gradient[size_t(n)][size_t(j)]);
    }
    msg().infof("    {} of crack {}: {} nodes, {} component(s)", field, crack->name, mesh.nodeCount(),
                out->componentCount());
    return out;
}

ConceptPtr creaChamp(const KeywordSet& kw, CommandContext&) {
    const std::string operation = kw.text("OPERATION");
    if (operation != "EXTR") throw NotImplemented("CREA_CHAMP/OPERATION='" + operation + "': only 'EXTR'");
    if (kw.has("FISSURE")) return crackField(kw);
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
