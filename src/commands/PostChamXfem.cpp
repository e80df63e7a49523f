// POST_CHAM_XFEM: the fields of an X-FEM result on the POST_MAIL_XFEM mesh (xfem_spec §7):
// DEPL of each lip at the duplicated nodes, SIEF_ELGA averaged per sub-cell; type and INST kept.
#include <fmt/format.h>

#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "fe/Model.hpp"
#include "fe/Result.hpp"
#include "parser/CommandRegistry.hpp"
#include "xfem/Visualisation.hpp"

namespace ma {
namespace {

ConceptPtr postChamXfem(const KeywordSet& kw, CommandContext&) {
    auto visuModel = kw.object<Model>("MODELE_VISU");
    auto input = kw.object<Result>("RESULTAT");
    auto out = xfem::visualisationResult(*input, visuModel);
    msg().infof("    {} order(s) of {} ({}) on the visualisation mesh: DEPL{}", out->steps.size(), input->name,
                input->typeName(),
                !out->steps.empty() && out->steps.front().gauss("SIEF_ELGA") ? ", SIEF_ELGA (mean per sub-cell)" : "");
    return out;
}

MA_REGISTER_COMMAND("POST_CHAM_XFEM", postChamXfem);

}  // namespace
}  // namespace ma
