#include "commands/FractureKeywords.hpp"

#include <fmt/format.h>

#include "core/Error.hpp"
#include "xfem/XfemModel.hpp"

namespace ma {

std::vector<const ResultStep*> fractureSteps(const Result& result, const KeywordSet& kw) {
    std::vector<const ResultStep*> steps;
    if (kw.has("NUME_ORDRE")) {
        for (auto order : kw.integers("NUME_ORDRE")) steps.push_back(&result.step(int(order)));
    } else if (kw.has("INST")) {
        const bool relative = kw.text("CRITERE") == "RELATIF";
        for (double inst : kw.reals("INST")) steps.push_back(&result.stepAtInst(inst, kw.real("PRECISION"), relative));
    } else {
        for (const auto& s : result.steps) steps.push_back(&s);
    }
    return steps;
}

void checkCrackResult(const Result& result, const xfem::Crack& crack, const std::string& keyword,
                      const std::string& command, bool thetaMethod) {
    const auto* xfemModel =
        result.model ? dynamic_cast<const xfem::XfemModel*>(result.model->enrichment.get()) : nullptr;
    bool inModel = false;
    if (xfemModel)
        for (const auto& c : xfemModel->cracks()) inModel = inModel || c.get() == &crack;
    if (!inModel)
        throw UserError(fmt::format("{}: crack {} is not a crack of the model of result {} (MODI_MODELE_XFEM)", keyword,
                                    crack.name, result.name));
    if (!crack.isCrack || crack.fronts.empty())
        throw UserError(fmt::format("{}: {} has no front in the mesh: there is no stress intensity to compute", keyword,
                                    crack.name));
    if (!result.material) throw UserError(fmt::format("result {} has no material field", result.name));
    if (!thetaMethod) return;
    for (const auto& load : result.loads) {
        if (!load.load->volumeForces.empty())
            throw NotImplemented(fmt::format(
                "{} with the load {} of result {}: volume forces enter the theta method's right-hand side, which "
                "miniaster does not compute yet",
                command, load.load->name, result.name));
        for (const auto& lip : load.load->lipPressures)
            if (lip.crack.get() != &crack)
                throw NotImplemented(fmt::format(
                    "{} on crack {} with the load {} of result {}: its pressure on the lips of another crack or "
                    "interface would enter the theta method of {}; miniaster computes the lip term of the crack "
                    "studied only",
                    command, crack.name, load.load->name, result.name, crack.name));
    }
}

}  // namespace ma
