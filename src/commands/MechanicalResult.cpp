#include "commands/MechanicalResult.hpp"

namespace ma::mechanics {

std::shared_ptr<Result> mechanicalResult(std::string kind, const std::shared_ptr<Model>& model,
                                         const std::shared_ptr<MaterialField>& material,
                                         const std::vector<LoadCase>& loads) {
    auto result = std::make_shared<Result>(std::move(kind));
    result->mesh = model->mesh;
    result->model = model;
    result->material = material;
    result->loads = loads;
    return result;
}

void archiveState(Result& result, const MechanicalProblem& problem, int order, double inst, bool displacement,
                  bool stresses) {
    ResultStep step;
    step.order = order;
    step.inst = inst;
    if (displacement) step.nodalFields.emplace_back("DEPL", problem.displacementField());
    if (stresses) step.gaussFields.emplace_back("SIEF_ELGA", problem.stressField());
    result.steps.push_back(std::move(step));
}

}  // namespace ma::mechanics
