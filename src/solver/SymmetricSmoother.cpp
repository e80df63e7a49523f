#include "solver/SymmetricSmoother.hpp"

#include <vector>

#include "solver/KrylovSettings.hpp"

namespace ma {

Mat upperTriangleOf(const CsrMatrix& B, size_t first, PetscInt size, MPI_Comm comm) {
    std::vector<PetscInt> rowStart{0}, cols;
    std::vector<PetscScalar> values;
    for (size_t k = 0; k < size_t(B.rows); ++k) {
        for (long long a = B.rowStart[k]; a < B.rowStart[k + 1]; ++a)
            if (size_t(B.cols[size_t(a)]) >= first + k)
                cols.push_back(B.cols[size_t(a)]), values.push_back(B.values[size_t(a)]);
        rowStart.push_back(PetscInt(cols.size()));
    }
    Mat upper = nullptr;
    checkPetsc(MatCreate(comm, &upper), "MatCreate");
    checkPetsc(MatSetSizes(upper, B.rows, B.rows, size, size), "MatSetSizes");
    checkPetsc(MatSetType(upper, MATSBAIJ), "MatSetType");
    // Only the call of the matrix's own type (sequential or parallel) acts.
    checkPetsc(MatSeqSBAIJSetPreallocationCSR(upper, 1, rowStart.data(), cols.data(), values.data()),
               "MatSeqSBAIJSetPreallocationCSR");
    checkPetsc(MatMPISBAIJSetPreallocationCSR(upper, 1, rowStart.data(), cols.data(), values.data()),
               "MatMPISBAIJSetPreallocationCSR");
    return upper;
}

bool smoothFinestOn(PC pc, Mat upper) {
    PetscInt levels = 0;
    KSP smoother = nullptr;
    PC inner = nullptr;
    Mat a = nullptr, p = nullptr;
    PetscBool sor = PETSC_FALSE;
    if (PCMGGetLevels(pc, &levels) != 0 || levels < 2 || PCMGGetSmoother(pc, levels - 1, &smoother) != 0 ||
        KSPGetOperators(smoother, &a, &p) != 0 || KSPGetPC(smoother, &inner) != 0)
        return false;
    PetscObjectTypeCompare(reinterpret_cast<PetscObject>(inner), PCSOR, &sor);
    if (!sor || a != p) return false;
    checkPetsc(KSPSetOperators(smoother, upper, upper), "KSPSetOperators");
    checkPetsc(KSPSetUp(smoother), "KSPSetUp (the finest smoother on the upper triangle)");
    return true;
}

}  // namespace ma
