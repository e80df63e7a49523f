// CALC_CHAMP: fields derived from a static result's SIEF_ELGA (post/NodeValues.hpp), stored in the
// result under their NOM_CHAM for the orders and cells chosen. The engine is in src/post.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "fe/Result.hpp"
#include "parser/CommandRegistry.hpp"
#include "post/NodeValues.hpp"

namespace ma {
namespace {

std::vector<ResultStep*> chosenSteps(Result& result, const KeywordSet& kw) {
    std::vector<ResultStep*> steps;
    if (kw.has("NUME_ORDRE")) {
        for (auto order : kw.integers("NUME_ORDRE")) steps.push_back(&result.step(int(order)));
    } else if (kw.has("INST")) {
        const bool relative = kw.text("CRITERE") == "RELATIF";
        for (double inst : kw.reals("INST"))
            steps.push_back(&result.step(result.stepAtInst(inst, kw.real("PRECISION"), relative).order));
    } else {
        for (auto& s : result.steps) steps.push_back(&s);
    }
    return steps;
}

// keep[cell] for the model's cells in GROUP_MA (every model cell with TOUT or by default).
std::vector<char> chosenCells(const Result& result, const KeywordSet& kw) {
    const Mesh& mesh = *result.mesh;
    std::vector<char> keep(size_t(mesh.cellCount()), 0);
    if (!kw.has("GROUP_MA")) {
        keep.assign(keep.size(), 1);
        return keep;
    }
    for (const auto& g : kw.texts("GROUP_MA"))
        for (int c : namedGroup(mesh, GroupKind::Cells, g, kw.pathOf("GROUP_MA"))) keep[size_t(c)] = 1;
    return keep;
}

template <class F>
void store(std::vector<std::pair<std::string, std::shared_ptr<F>>>& fields, const std::string& name,
           std::shared_ptr<F> field) {
    field->name = name;
    for (auto& [n, f] : fields)
        if (n == name) {
            f = std::move(field);
            return;
        }
    fields.emplace_back(name, std::move(field));
}

// The CONTRAINTE fields of one step, from its SIEF_ELGA on the chosen cells.
void stressFields(ResultStep& step, const Result& result, const std::vector<std::string>& asked,
                  const std::vector<char>& keep, const KeywordSet& kw) {
    const auto sief = step.gauss("SIEF_ELGA");
    if (!sief)
        throw UserError(
            fmt::format("{}: result {} has no SIEF_ELGA at NUME_ORDRE {} (the stresses CALC_CHAMP "
                        "derives its fields from; compute them with OPTION='SIEF_ELGA')",
                        kw.pathOf("CONTRAINTE"), result.name, step.order));
    const auto elga = post::restrictToCells(*sief, keep);
    if (elga->cells.empty())
        throw UserError(kw.pathOf("GROUP_MA") + ": none of these cells carries an element of the model of " +
                        result.name);
    const Enrichment* enrichment = result.model ? result.model->enrichment.get() : nullptr;
    std::shared_ptr<GaussField> elno;
    auto nodes = [&] { return elno ? elno : (elno = post::nodeValues(*elga, enrichment)); };
    for (const auto& name : asked) {
        if (name == "SIGM_ELGA") store(step.gaussFields, name, std::make_shared<GaussField>(*elga));
        else if (name == "SIGM_ELNO" || name == "SIEF_ELNO")
            store(step.gaussFields, name, std::make_shared<GaussField>(*nodes()));
        else if (name == "SIGM_NOEU" || name == "SIEF_NOEU")
            store(step.nodalFields, name, post::nodalAverage(*nodes()));
        else throw NotImplemented(kw.pathOf("CONTRAINTE") + ": " + name + " is not computed by miniaster");
    }
}

ConceptPtr calcChamp(const KeywordSet& kw, CommandContext& ctx) {
    auto input = kw.object<Result>("RESULTAT");
    if (ctx.reused && ctx.reused != input) throw UserError("CALC_CHAMP: reuse= must name the result given by RESULTAT");
    if (kw.has("MODELE") && kw.object<Model>("MODELE") != input->model)
        throw UserError(kw.pathOf("MODELE") + ": not the model of " + input->name +
                        "; miniaster computes the fields on the result's own model");
    if (!input->mesh) throw UserError(kw.pathOf("RESULTAT") + ": result " + input->name + " has no mesh");
    // Without reuse=, a new result sharing the input's fields, the new ones added to it.
    auto result = ctx.reused ? input : std::make_shared<Result>(*input);
    const auto asked = kw.texts("CONTRAINTE");
    const auto keep = chosenCells(*result, kw);
    const auto steps = chosenSteps(*result, kw);
    for (ResultStep* step : steps) stressFields(*step, *result, asked, keep, kw);
    msg().infof("    {} computed at {} order(s) of {}", fmt::join(asked, ", "), steps.size(), input->name);
    return result;
}

MA_REGISTER_COMMAND("CALC_CHAMP", calcChamp);

}  // namespace
}  // namespace ma
