#pragma once
// The result of the static analyses, built the same way by MECA_STATIQUE (evol_elas) and
// STAT_NON_LINE (evol_noli): the model and material of the problem, then its archived states.
#include <memory>
#include <string>

#include "fe/MechanicalProblem.hpp"
#include "fe/Result.hpp"

namespace ma::mechanics {

// An empty result of `kind` ("evol_elas", "evol_noli") on this model, material and loads.
std::shared_ptr<Result> mechanicalResult(std::string kind, const std::shared_ptr<Model>& model,
                                         const std::shared_ptr<MaterialField>& material,
                                         const std::vector<LoadCase>& loads);

// Archives the problem's current state as NUME_ORDRE `order` at `inst`: DEPL when `displacement`,
// SIEF_ELGA when `stresses`.
void archiveState(Result& result, const MechanicalProblem& problem, int order, double inst, bool displacement,
                  bool stresses);

}  // namespace ma::mechanics
