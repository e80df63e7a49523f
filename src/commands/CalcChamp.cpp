// CALC_CHAMP: fields derived from a static result's SIEF_ELGA (post/NodeValues.hpp,
// post/EquivalentStress.hpp), its strains (post/Strains.hpp) and its nodal forces
// (post/NodalForces.hpp), stored in the result under their NOM_CHAM for the orders and cells chosen.
// The engine is in src/post.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <optional>

#include "commands/MechanicsKeywords.hpp"
#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "fe/Result.hpp"
#include "parser/CommandRegistry.hpp"
#include "post/EquivalentStress.hpp"
#include "post/NodalForces.hpp"
#include "post/NodeValues.hpp"
#include "post/Strains.hpp"

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

// The fields derived from one GaussField of a result at the chosen cells, each computed once when
// asked: the field itself (ELGA), its values at the cells' nodes (ELNO), and the equivalent stresses
// of each (SIEQ_ELGA from ELGA, SIEQ_ELNO from ELNO); _NOEU is the nodal mean of its _ELNO, as
// code_aster derives every _NOEU option.
class DerivedFields {
public:
    DerivedFields(const GaussField& field, const std::vector<char>& keep, const KeywordSet& kw, const Result& result)
        : elga_(post::restrictToCells(field, keep)),
          enrichment_(result.model ? result.model->enrichment.get() : nullptr) {
        if (elga_->cells.empty())
            throw UserError(kw.pathOf("GROUP_MA") + ": none of these cells carries an element of the model of " +
                            result.name);
    }

    // Stores NOM_CHAM `name` (suffix _ELGA, _ELNO or _NOEU; SIEQ_* the equivalent stresses).
    void store(ResultStep& step, const std::string& name) {
        const bool equivalent = name.rfind("SIEQ_", 0) == 0;
        const std::string place = name.substr(name.size() - 4);
        if (place == "ELGA") ma::store(step.gaussFields, name, std::make_shared<GaussField>(*points(equivalent)));
        else if (place == "ELNO") ma::store(step.gaussFields, name, std::make_shared<GaussField>(*nodes(equivalent)));
        else ma::store(step.nodalFields, name, post::nodalAverage(*nodes(equivalent)));
    }

private:
    std::shared_ptr<GaussField> points(bool equivalent) {
        if (!equivalent) return elga_;
        return eqElga_ ? eqElga_ : (eqElga_ = post::equivalentStresses(*elga_));
    }
    std::shared_ptr<GaussField> nodes(bool equivalent) {
        if (!elno_) elno_ = post::nodeValues(*elga_, enrichment_);
        if (!equivalent) return elno_;
        return eqElno_ ? eqElno_ : (eqElno_ = post::equivalentStresses(*elno_));
    }

    std::shared_ptr<GaussField> elga_, elno_, eqElga_, eqElno_;
    const Enrichment* enrichment_;
};

// The CONTRAINTE and CRITERES fields of one step, from its SIEF_ELGA on the chosen cells.
void stressFields(ResultStep& step, const Result& result, const std::vector<std::string>& asked,
                  const std::vector<char>& keep, const KeywordSet& kw) {
    const auto sief = step.gauss("SIEF_ELGA");
    if (!sief)
        throw UserError(
            fmt::format("{}: result {} has no SIEF_ELGA at NUME_ORDRE {} (the stresses CALC_CHAMP "
                        "derives its fields from; compute them with OPTION='SIEF_ELGA')",
                        kw.pathOf(kw.has("CONTRAINTE") ? "CONTRAINTE" : "CRITERES"), result.name, step.order));
    DerivedFields stress(*sief, keep, kw, result);
    for (const auto& name : asked) stress.store(step, name);
}

// The DEFORMATION fields of one step (EPSI_ELGA/ELNO/NOEU), from its displacement.
void strainFields(ResultStep& step, const Result& result, const post::Strains& strains,
                  const std::vector<std::string>& asked, const std::vector<char>& keep, const KeywordSet& kw) {
    DerivedFields strain(*strains.atPoints(step), keep, kw, result);
    for (const auto& name : asked) strain.store(step, name);
}

// The FORCE fields of one step; the sum of each displacement component of REAC_NODA in the .mess
// (the reactions balance the loads: it is minus the resultant of the applied loads).
void forceFields(ResultStep& step, const post::NodalForces& forces, const std::vector<std::string>& asked) {
    for (const auto& name : asked) {
        auto field = name == "FORC_NODA" ? forces.internalForces(step) : forces.reactions(step);
        if (name == "REAC_NODA") {
            std::string sums;
            for (const char* c : {"DX", "DY", "DZ"})
                if (const int k = field->componentIndex(c); k >= 0) {
                    double sum = 0.0;
                    for (int n = 0; n < field->mesh->nodeCount(); ++n)
                        if (field->has(n, k)) sum += field->at(n, k);
                    sums += fmt::format(" {} {:.6e}", c, sum);
                }
            msg().infof("    REAC_NODA NUME_ORDRE {}: sum over the nodes{}", step.order, sums);
        }
        store(step.nodalFields, name, std::move(field));
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
    const auto option = [&](const char* keyword) {
        return kw.has(keyword) ? kw.texts(keyword) : std::vector<std::string>{};
    };
    auto stresses = option("CONTRAINTE");
    const auto criteria = option("CRITERES"), strain = option("DEFORMATION"), force = option("FORCE");
    stresses.insert(stresses.end(), criteria.begin(), criteria.end());
    const auto keep = chosenCells(*result, kw);
    const auto steps = chosenSteps(*result, kw);
    std::optional<post::NodalForces> forces;
    if (!force.empty()) forces.emplace(*result, kw.has("EXCIT") ? mechanics::loadCases(kw) : result->loads, keep);
    std::optional<post::Strains> strains;
    if (!strain.empty())
        strains.emplace(*result, kw.has("CHAM_MATER") ? kw.object<MaterialField>("CHAM_MATER") : result->material);
    for (ResultStep* step : steps) {
        if (!stresses.empty()) stressFields(*step, *result, stresses, keep, kw);
        if (strains) strainFields(*step, *result, *strains, strain, keep, kw);
        if (forces) forceFields(*step, *forces, force);
    }
    auto asked = stresses;
    asked.insert(asked.end(), strain.begin(), strain.end());
    asked.insert(asked.end(), force.begin(), force.end());
    msg().infof("    {} computed at {} order(s) of {}", fmt::join(asked, ", "), steps.size(), input->name);
    return result;
}

MA_REGISTER_COMMAND("CALC_CHAMP", calcChamp);

}  // namespace
}  // namespace ma
