#pragma once
// CALC_CHAMP's FORCE fields of a static result, in the unknowns of its displacement (DX, DY[, DZ],
// H1X ...; docs/post.md):
//   FORC_NODA = sum over the chosen elements of int B^T sigma(u)  (the element forces on the nodes)
//   REAC_NODA = FORC_NODA - F_ext(INST)  (F_ext: the loads' nodal forces; Dirichlet conditions give
//               none), so that at a constrained unknown it is the support's reaction on the body and
//               elsewhere the residual of the solve.
// Contact (Nitsche) terms are not element forces: as code_aster's X-FEM contact forces, they show in
// REAC_NODA, on the enriched unknowns of the cut cells.
#include <memory>
#include <vector>

#include "fe/Discretisation.hpp"
#include "fe/LoadCase.hpp"
#include "fe/Result.hpp"

namespace ma::post {

class NodalForces {
public:
    // The elements of the cells flagged in `cells` (a flag per mesh cell), the loads applied on
    // flagged cells only (code_aster computes both on the ligrel of GROUP_MA).
    NodalForces(const Result& result, const std::vector<LoadCase>& loads, const std::vector<char>& cells);

    std::shared_ptr<NodalField> internalForces(const ResultStep& step) const;  // FORC_NODA
    std::shared_ptr<NodalField> reactions(const ResultStep& step) const;       // REAC_NODA

private:
    std::vector<double> elementForces(const ResultStep& step) const;
    std::shared_ptr<NodalField> toField(const std::vector<double>& f) const;

    const Result& result_;
    Discretisation space_;
    std::vector<char> cells_;
    std::vector<LoadCase> loads_;  // restricted to the flagged cells
};

}  // namespace ma::post
