// MECA_STATIQUE: linear static analysis (commands_spec §8.6). One linear solve per instant
// (INST, LIST_INST [+ INST_FIN], or a single step at INST 0 when absent); orders 1, 2, ...
// Each step stores DEPL and (OPTION='SIEF_ELGA', the default) SIEF_ELGA.
#include <fmt/format.h>

#include <chrono>

#include "commands/LegacyContactLoad.hpp"
#include "commands/MechanicalResult.hpp"
#include "commands/MechanicsKeywords.hpp"
#include "core/Messages.hpp"
#include "fe/MechanicalProblem.hpp"
#include "parser/CommandRegistry.hpp"

namespace ma {
namespace {

ConceptPtr mecaStatique(const KeywordSet& kw, CommandContext& ctx) {
    const auto t0 = std::chrono::steady_clock::now();
    if (ctx.reused) throw NotImplemented("MECA_STATIQUE with reuse= is not supported by miniaster");
    auto model = kw.object<Model>("MODELE");
    if (!kw.has("CHAM_MATER")) throw UserError("MECA_STATIQUE: CHAM_MATER is required (the elements need a material)");
    auto material = kw.object<MaterialField>("CHAM_MATER");
    if (material->mesh != model->mesh)
        throw UserError("MECA_STATIQUE: CHAM_MATER " + material->name + " is not defined on the mesh of MODELE " +
                        model->name);
    std::vector<double> instants{0.0};
    if (kw.has("INST")) instants = {kw.real("INST")};
    if (kw.has("LIST_INST")) {
        instants = kw.object<RealList>("LIST_INST")->values;
        if (kw.has("INST_FIN")) {
            const double fin = kw.real("INST_FIN");
            std::erase_if(instants, [&](double t) { return t > fin + 1e-12 * std::max(1.0, std::abs(fin)); });
        }
    }
    const auto loads = mechanics::loadCases(kw);
    mechanics::refuseContactLoads(loads, "MECA_STATIQUE");
    MechanicalProblem problem(model, material, loads, mechanics::solverOptions(kw, ctx.info));
    auto result = mechanics::mechanicalResult("evol_elas", model, material, loads);
    const ConvergenceOptions linear;  // one solve, no convergence test: the problem is linear
    const bool stresses = kw.text("OPTION") == "SIEF_ELGA";
    int order = 0;
    for (double inst : instants) {
        problem.resetState();
        // No solve follows the last: SIEF_ELGA without the factors, from the residual's point loop.
        using After = MechanicalProblem::AfterSolve;
        const After after = inst != instants.back() ? After::KeepFactors
                            : stresses              ? After::ReleaseFactorsKeepStresses
                                                    : After::ReleaseFactors;
        const auto report = problem.solveIncrement(inst, linear, after);
        mechanics::archiveState(*result, problem, ++order, inst, true, stresses);
        msg().infof("    NUME_ORDRE {} INST {}: max |R| after the solve = {:.3e} (relative {:.3e})", order, inst,
                    report.maxResidual, report.relativeResidual);
    }
    msg().infof("    MECA_STATIQUE: {} step(s), {:.3f} s", instants.size(), secondsSince(t0));
    return result;
}

MA_REGISTER_COMMAND("MECA_STATIQUE", mecaStatique);

}  // namespace
}  // namespace ma
