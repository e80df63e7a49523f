#pragma once
// The CSR pattern of a mechanical problem's matrix (equations of DirichletConstraints): the
// element couplings (dofs of nodes sharing an element), the Lagrange multiplier rows and columns,
// and the couplings an AdditionalTerms declares. Rows sorted; built on the workers with the same
// result for any number of them.
#include "fe/AdditionalTerms.hpp"
#include "fe/DirichletConstraints.hpp"
#include "fe/Discretisation.hpp"
#include "solver/SparseMatrix.hpp"

namespace ma {

// The pattern (values left empty: allocated by the first assembly); logs its size and cost.
// Distributed (docs/mpi.md): the element couplings of this process's elements only, unless
// `allElements` (the whole matrix's pattern, for the ordering on rank 0); multiplier rows and the
// additional terms' couplings always whole.
CsrMatrix buildSparsityPattern(const Discretisation& space, const DirichletConstraints& constraints,
                               const AdditionalTerms* additional, bool allElements = false);

}  // namespace ma
