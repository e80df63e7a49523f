#pragma once
// CALC_CHAMP DEFORMATION: the small strains of a static result's displacement at the points of its
// SIEF_ELGA (X-FEM sub-cell points included), EPSI_ELGA; ELNO and NOEU follow as for the stresses
// (post/NodeValues.hpp).
#include <memory>

#include "fe/Discretisation.hpp"
#include "fe/Result.hpp"

namespace ma::post {

class Strains {
public:
    // On the result's model with `material` (the result's own, or CALC_CHAMP's CHAM_MATER for a
    // result that has none, such as POST_CHAM_XFEM's); UserError when either is missing.
    Strains(const Result& result, std::shared_ptr<const MaterialField> material);

    std::shared_ptr<GaussField> atPoints(const ResultStep& step) const;  // EPSI_ELGA on every element

private:
    const Result& result_;
    Discretisation space_;
};

}  // namespace ma::post
