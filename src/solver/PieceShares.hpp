#pragma once
// How the piece basis is shared between processes (solver/PiecesOnProcesses.hpp; docs/solver.md,
// "The piece basis on several processes").
#include <vector>

#include "solver/PieceBasis.hpp"

namespace ma {

// The share of each copy for `processes` processes, by recursive coordinate bisection of the nodes
// (the groups of copies and equations that read one another), each cut across the longest extent of
// its part, so that a plate or a slab is never cut through its thickness, where the couplings are
// strongest. Empty when there are fewer nodes than processes.
std::vector<int> bisectCopies(const PieceBasis& basis, int processes);

// The share of equation i under ownerOfCopy: that of the first copy T's row i reads (T is node-local,
// so every copy it reads is in the same share); -1 for an equation that reads none.
inline int shareOfEquation(const PieceBasis& basis, const std::vector<int>& ownerOfCopy, int i) {
    const CsrMatrix& T = basis.T;
    const long long first = T.rowStart[size_t(i)];
    if (T.rowStart[size_t(i) + 1] == first) return -1;
    return ownerOfCopy[size_t(T.cols[size_t(first)] / basis.blockSize)];
}

// The shares of ownerOfCopy (share of each copy); the copies are renumbered share after share (T,
// padding, modes and coordinates follow). Empty (the basis unchanged) when a share would be empty.
std::vector<PieceShare> shareCopies(PieceBasis& basis, const std::vector<int>& ownerOfCopy, int processes);

}  // namespace ma
