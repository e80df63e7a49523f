// STAT_NON_LINE restricted to what ssnv511 needs (commands_spec §8.7): RELATION='ELAS' in small
// strains, fixed loads scaled by FONC_MULT, Newton iterations with RESI_GLOB_MAXI /
// RESI_GLOB_RELA / ITER_GLOB_MAXI / ARRET. Order 0 is the initial state (zero displacement at the
// first instant); one step per later instant up to INST_FIN; ARCHIVAGE selects the stored steps.
//
// CONTACT (DEFI_CONTACT, FORMULATION='XFEM'): each increment runs the contact loop of
// src/contact (statuses frozen during a Newton solve, then updated; docs/contact.md).
#include <fmt/format.h>

#include <chrono>
#include <cmath>

#include "commands/LegacyContactLoad.hpp"
#include "commands/MechanicalResult.hpp"
#include "commands/MechanicsKeywords.hpp"
#include "contact/ContactLoop.hpp"
#include "core/Messages.hpp"
#include "fe/MechanicalProblem.hpp"
#include "parser/CommandRegistry.hpp"

namespace ma {
namespace {

bool near(double a, double b, double precision) { return std::abs(a - b) <= precision * std::max(1.0, std::abs(b)); }

// CONVERGENCE (the catalogue gives RESI_GLOB_RELA = 1e-6 when neither criterion is given).
ConvergenceOptions convergenceOptions(const KeywordSet& kw) {
    const KeywordSet& o = kw.factor("CONVERGENCE").front();
    ConvergenceOptions conv;
    conv.maxIterations = static_cast<int>(o.integer("ITER_GLOB_MAXI"));
    conv.resiGlobMaxi = o.has("RESI_GLOB_MAXI") ? o.real("RESI_GLOB_MAXI") : -1.0;
    conv.resiGlobRela = o.has("RESI_GLOB_RELA") ? o.real("RESI_GLOB_RELA") : -1.0;
    conv.stopOnFailure = o.text("ARRET") == "OUI";
    return conv;
}

// ELAS in small strains everywhere: the cells COMPORTEMENT names matter only for being in the mesh
// (an unknown GROUP_MA or MAILLE is an error, as in code_aster).
void refuseUnsupportedBehaviour(const KeywordSet& kw, const Mesh& mesh) {
    bool localIntegration = false;
    for (const auto& occ : kw.factor("COMPORTEMENT")) {
        mechanics::selectedCells(mesh, occ);
        if (occ.text("RELATION") != "ELAS")
            throw NotImplemented(occ.pathOf("RELATION") + "='" + occ.text("RELATION") + "': only ELAS is supported");
        if (occ.text("DEFORMATION") != "PETIT")
            throw NotImplemented(occ.pathOf("DEFORMATION") + "='" + occ.text("DEFORMATION") + "': only PETIT");
        for (const char* k : {"RESI_INTE_RELA", "ITER_INTE_MAXI", "ITER_INTE_PAS"}) localIntegration |= occ.has(k);
    }
    if (localIntegration)
        msg().infof(
            "    COMPORTEMENT: RESI_INTE_RELA, ITER_INTE_MAXI and ITER_INTE_PAS control the local integration "
            "of non-linear behaviours; with RELATION='ELAS' there is none, they are not used");
    if (kw.text("METHODE") != "NEWTON")
        throw NotImplemented("STAT_NON_LINE/METHODE='" + kw.text("METHODE") + "': only NEWTON");
}

// INCREMENT: the instants of LIST_INST from `first` (the initial state) to `last`.
struct Increments {
    std::vector<double> list;
    size_t first = 0, last = 0;
};

Increments incrementsOf(const KeywordSet& kw) {
    const auto& incr = kw.factor("INCREMENT");
    if (incr.empty()) throw UserError("STAT_NON_LINE: INCREMENT/LIST_INST is required");
    const KeywordSet& inc = incr.front();
    Increments out;
    out.list = inc.object<RealList>("LIST_INST")->values;
    const auto& list = out.list;
    const double precision = inc.real("PRECISION");
    auto indexOf = [&](double t, const std::string& key) {
        for (size_t i = 0; i < list.size(); ++i)
            if (near(list[i], t, precision)) return i;
        throw UserError(fmt::format("{} = {} is not an instant of LIST_INST", inc.pathOf(key), t));
    };
    out.last = list.size() - 1;
    if (inc.has("INST_INIT")) out.first = indexOf(inc.real("INST_INIT"), "INST_INIT");
    if (inc.has("NUME_INST_INIT")) out.first = static_cast<size_t>(inc.integer("NUME_INST_INIT"));
    if (inc.has("INST_FIN")) out.last = indexOf(inc.real("INST_FIN"), "INST_FIN");
    if (inc.has("NUME_INST_FIN")) out.last = static_cast<size_t>(inc.integer("NUME_INST_FIN"));
    if (out.first >= list.size() || out.last >= list.size() || out.last <= out.first)
        throw UserError(
            fmt::format("STAT_NON_LINE/INCREMENT: no step between instants #{} and #{} of LIST_INST "
                        "({} instants)",
                        out.first, out.last, list.size()));
    return out;
}

// ARCHIVAGE: which instants are stored (every one unless it restricts them; the last computed
// one always) and which fields are left out.
struct Archiving {
    std::vector<char> instants;  // per instant of LIST_INST
    std::vector<std::string> excluded;
    bool keeps(const std::string& field) const {
        return std::find(excluded.begin(), excluded.end(), field) == excluded.end();
    }
};

Archiving archivingOf(const KeywordSet& kw, const Increments& steps) {
    const auto& list = steps.list;
    Archiving out{std::vector<char>(list.size(), 1), {}};
    const auto& a = kw.factor("ARCHIVAGE");
    if (a.empty()) return out;
    const KeywordSet& o = a.front();
    if (o.has("CHAM_EXCLU")) out.excluded = o.texts("CHAM_EXCLU");
    const double aprec = o.real("PRECISION");
    std::vector<double> wanted;
    if (o.has("LIST_INST")) wanted = o.object<RealList>("LIST_INST")->values;
    if (o.has("INST")) wanted = o.reals("INST");
    auto& archive = out.instants;
    if (!wanted.empty()) {
        std::fill(archive.begin(), archive.end(), 0);
        for (size_t i = 0; i < list.size(); ++i)
            for (double t : wanted)
                if (near(list[i], t, aprec)) archive[i] = 1;
    }
    if (o.has("PAS_ARCH")) {
        const long long pas = o.integer("PAS_ARCH");
        if (pas <= 0) throw UserError(o.pathOf("PAS_ARCH") + " must be positive");
        for (size_t i = steps.first; i < list.size(); ++i)
            archive[i] = (i - steps.first) % static_cast<size_t>(pas) == 0;
    }
    archive[steps.last] = 1;
    return out;
}

// Order 0's SIEF_ELGA (sigma = 0 at u = 0) on the points of the last archived one, made once the
// factors are freed: it is not alive beside them (92 bytes per Gauss point, 0.4 GB at 2e6 dofs).
void addInitialStresses(Result& result) {
    auto zero = std::make_shared<GaussField>(*result.steps.back().gaussFields.front().second);
    std::fill(zero->values.begin(), zero->values.end(), 0.0);
    result.steps.front().gaussFields.emplace_back("SIEF_ELGA", std::move(zero));
}

// One increment to `inst`: Newton iterations, inside the contact loop when there is contact.
IncrementReport solveIncrement(MechanicalProblem& problem, contact::ContactTerms* contactTerms, size_t increment,
                               double inst, const ConvergenceOptions& conv) {
    if (!contactTerms) return problem.solveIncrement(inst, conv);
    const auto cr = contact::solveIncrementWithContact(problem, *contactTerms, inst, conv);
    IncrementReport report = cr.lastNewton;
    report.iterations = cr.newtonIterations;
    msg().infof("    increment {} (INST {}): {} contact iteration(s), {} active contact points of {}", increment, inst,
                cr.contactIterations, cr.last.active, cr.last.points);
    return report;
}

ConceptPtr statNonLine(const KeywordSet& kw, CommandContext& ctx) {
    const auto t0 = std::chrono::steady_clock::now();
    if (ctx.reused) throw NotImplemented("STAT_NON_LINE with reuse= (continuation) is not supported by miniaster");
    auto model = kw.object<Model>("MODELE");
    refuseUnsupportedBehaviour(kw, *model->mesh);
    auto material = kw.object<MaterialField>("CHAM_MATER");
    if (material->mesh != model->mesh)
        throw UserError("STAT_NON_LINE: CHAM_MATER " + material->name + " is not defined on the mesh of MODELE " +
                        model->name);
    const Increments steps = incrementsOf(kw);
    const auto& list = steps.list;
    const size_t first = steps.first, last = steps.last;
    const ConvergenceOptions conv = convergenceOptions(kw);
    const Archiving archiving = archivingOf(kw, steps);

    const auto loads = mechanics::loadCases(kw);
    const auto definition = mechanics::contactOfTheSolve(kw, loads);
    MechanicalProblem problem(model, material, loads, mechanics::solverOptions(kw, ctx.info));
    std::shared_ptr<contact::ContactTerms> contactTerms;
    if (definition) {
        if (definition->model->enrichment != model->enrichment)
            throw UserError(fmt::format("the contact {} was defined on model {}, not on MODELE {}", definition->name,
                                        definition->model->name, model->name));
        contactTerms = contact::attachContact(problem, *material, definition);
    }
    auto result = mechanics::mechanicalResult("evol_noli", model, material, loads);
    int order = 0;
    auto store = [&](double inst, bool stresses) {
        mechanics::archiveState(*result, problem, order++, inst, archiving.keeps("DEPL"),
                                stresses && archiving.keeps("SIEF_ELGA"));
    };
    store(list[first], last == first);  // initial state u = 0; its SIEF_ELGA: addInitialStresses
    int totalIterations = 0;
    for (size_t i = first + 1; i <= last; ++i) {
        const IncrementReport report = solveIncrement(problem, contactTerms.get(), i - first, list[i], conv);
        totalIterations += report.iterations;
        if (i == last) problem.releaseFactorisation();  // no solve follows
        msg().infof("    increment {} (INST {}): {} Newton iteration(s), RESI_GLOB_RELA {:.3e}, RESI_GLOB_MAXI {:.3e}",
                    i - first, list[i], report.iterations, report.relativeResidual, report.maxResidual);
        if (archiving.instants[i]) store(list[i], true);
    }
    if (last > first && archiving.keeps("SIEF_ELGA")) addInitialStresses(*result);
    msg().infof("    STAT_NON_LINE: {} increment(s), {} Newton iteration(s), {} archived order(s), {:.3f} s",
                last - first, totalIterations, result->steps.size(), secondsSince(t0));
    return result;
}

MA_REGISTER_COMMAND("STAT_NON_LINE", statNonLine);

}  // namespace
}  // namespace ma
