#pragma once
// Assembly of a mechanical problem's matrix into its pattern (fe/SparsityPattern.hpp): element
// stiffnesses, the tangent of the additional terms and the scaled Lagrange multiplier blocks
//     [ K        alpha*C^T ]
//     [ alpha*C  0         ]     alpha = mean |K_ii| over the free dofs.
// Element matrices are computed on the workers and added in element order: the same bits for any
// number of workers.
#include <vector>

#include "fe/AdditionalTerms.hpp"
#include "fe/DirichletConstraints.hpp"
#include "fe/Discretisation.hpp"
#include "solver/SparseMatrix.hpp"

namespace ma {

// Fills matrix.values (zeroed first) at state u (the additional terms' tangent depends on it);
// returns the multiplier scaling alpha. Logs the cost.
double assembleSystemMatrix(const Discretisation& space, const DirichletConstraints& constraints,
                            const AdditionalTerms* additional, const std::vector<double>& u, CsrMatrix& matrix);

}  // namespace ma
