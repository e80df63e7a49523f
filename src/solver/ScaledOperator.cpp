#include "solver/ScaledOperator.hpp"

#include <algorithm>
#include <span>

#include "core/Mpi.hpp"

namespace ma {

void ScaledOperator::apply(const double* x, double* y) {
    if (basis) return applyInPieces(x, y);
    const std::vector<double>& s = *scale;
    const size_t n = s.size();
    work.resize(n);
    for (size_t i = 0; i < n; ++i) work[i] = s[i] * x[i];
    const std::span<double> out(y, n);
    A->multiply(work, out);
    if (distributed) mpi::sum(out);
    for (size_t i = 0; i < n; ++i) y[i] *= s[i];
}

void ScaledOperator::applyInPieces(const double* x, double* y) {
    const std::vector<double>& s = *scale;
    const size_t n = s.size();
    work.resize(n), equations.resize(size_t(A->rows)), product.resize(size_t(A->rows));
    if (shared) shared->gather(basis->blockSize, x, work.data());
    else std::copy(x, x + n, work.begin());
    for (size_t i = 0; i < n; ++i) work[i] *= s[i];
    toEquations(*basis, work.data(), equations.data());
    A->multiply(equations, product);
    size_t first = 0, m = n;
    if (shared) {
        shared->sumMine(product, mine);
        toPieces(*basis, shared->mine(), mine.data(), y);
        first = size_t(basis->blockSize * shared->mine().copyBegin);
        m = size_t(shared->mine().unknowns(basis->blockSize));
    } else {
        toPieces(*basis, product.data(), y);
    }
    for (size_t i = 0; i < m; ++i) y[i] = basis->padding[first + i] ? x[i] : y[i] * s[first + i];
}

PetscErrorCode multiplyScaled(Mat m, Vec x, Vec y) {
    void* context = nullptr;
    PetscCall(MatShellGetContext(m, &context));
    const PetscScalar* xv = nullptr;
    PetscScalar* yv = nullptr;
    PetscCall(VecGetArrayRead(x, &xv));
    PetscCall(VecGetArray(y, &yv));
    static_cast<ScaledOperator*>(context)->apply(xv, yv);
    PetscCall(VecRestoreArray(y, &yv));
    PetscCall(VecRestoreArrayRead(x, &xv));
    return 0;
}

}  // namespace ma
