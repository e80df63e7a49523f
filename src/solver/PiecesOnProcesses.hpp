#pragma once
// The piece basis on several processes (MATR_DISTRIBUEE with GAMG, ML or BOOMER; docs/solver.md,
// "The piece basis on several processes"). Every process holds the whole T and its own cells' part
// of A. Each owns a share of the copies and the equations that read them (PieceShare): it builds
// its rows of S T^T A T for PETSc's parallel preconditioner, and the Krylov operator multiplies the
// whole vector of copies by its equations' rows of the summed A.
#include <vector>

#include "solver/PieceShares.hpp"

namespace ma {

struct SharedPieces {
    std::vector<PieceShare> shares;  // one per process, by rank
    int rank = 0;

    bool active() const { return !shares.empty(); }
    const PieceShare& mine() const { return shares[static_cast<size_t>(rank)]; }
    // The whole vector of unknowns from every process's share of it (a collective call).
    void gather(int blockSize, const double* mine, double* whole) const;
    // The sum over the processes of a vector of equations, this process's share's equations of it
    // (in mine().equations' order; a collective call).
    void sumMine(const std::vector<double>& equations, std::vector<double>& mine) const;
};

// Relabels the shares of ownerOfCopy (bisectCopies) so that each process gets the share whose
// equations hold the most entries of its own part of K: the fewest rows then travel to another
// process in summedShareRows (a collective call).
void matchSharesToParts(std::vector<int>& ownerOfCopy, const PieceBasis& basis, const CsrMatrix& part);

// The rows of this process's share's equations of A summed over the processes (in its equations'
// order, global columns; a collective call): part is this process's part of A (its own cells).
CsrMatrix summedShareRows(const SharedPieces& shared, const CsrMatrix& part);

}  // namespace ma
