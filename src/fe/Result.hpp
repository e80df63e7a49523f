#pragma once
// A result (evol_elas of MECA_STATIQUE, evol_noli of STAT_NON_LINE, also POST_CHAM_XFEM's
// output): the model and material it was computed on and its archived steps.
#include <memory>
#include <string>
#include <vector>

#include "core/Concept.hpp"
#include "fe/LoadCase.hpp"
#include "fe/Material.hpp"
#include "fe/Model.hpp"
#include "fields/Fields.hpp"

namespace ma {

class Result : public Concept {
public:
    explicit Result(std::string kind = "evol_elas") : kind_(std::move(kind)) {}
    std::string typeName() const override { return kind_; }

    std::shared_ptr<const Mesh> mesh;
    std::shared_ptr<Model> model;
    std::shared_ptr<MaterialField> material;
    std::vector<LoadCase> loads;  // EXCIT of the analysis (CALC_CHAMP REAC_NODA subtracts them)
    std::vector<ResultStep> steps;

    // The step with this NUME_ORDRE; UserError naming the result when absent.
    const ResultStep& step(int order) const;
    ResultStep& step(int order);
    // The step at this INST within a relative/absolute precision.
    const ResultStep& stepAtInst(double inst, double precision, bool relative) const;

private:
    std::string kind_;
};

}  // namespace ma
