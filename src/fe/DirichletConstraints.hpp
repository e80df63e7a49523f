#pragma once
// Dirichlet conditions of a mechanical problem at one instant (docs/fe.md): every condition is a
// linear relation sum c_i u_i = v. One-term relations are eliminated (u_i = v/c), relations with
// several terms keep their free dofs and become Lagrange multiplier rows; inactive Heaviside slots
// and enriched dofs no element uses are fixed to 0 (code_aster's xteddl).
#include <utility>
#include <vector>

#include "fe/Discretisation.hpp"
#include "fe/LoadCase.hpp"

namespace ma {

struct DirichletConstraints {
    std::vector<char> fixed;         // per unknown: eliminated
    std::vector<double> fixedValue;  // its value when eliminated
    std::vector<int> eq;             // unknown -> equation (-1: eliminated)
    int freeCount = 0;               // equations of the free unknowns (the multiplier rows follow)
    struct Relation {
        std::vector<std::pair<int, double>> terms;  // free dofs only
        double value = 0.0;                         // right-hand side after substitution of eliminated dofs
    };
    std::vector<Relation> multi;  // one Lagrange multiplier each
    int unattached = 0;           // enriched dofs neutralised because no element uses them

    int equationCount() const { return freeCount + static_cast<int>(multi.size()); }
    // Same eliminated unknowns and same multiplier terms (values may differ): the matrix pattern
    // and the factorisation can be kept.
    bool sameStructure(const DirichletConstraints& o) const;
};

// The constraints of the loads at instant inst (values x FONC_MULT(INST)) for numbering().size()
// + extraUnknowns unknowns. UserError for conflicting values or a relation on a dof the model lacks.
DirichletConstraints buildDirichletConstraints(const Discretisation& space, const std::vector<LoadCase>& loads,
                                               double inst, int extraUnknowns);

}  // namespace ma
