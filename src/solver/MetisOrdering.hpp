#pragma once
// Fill-reducing ordering by nested dissection (METIS_NodeND, libmetis) of the graph of a
// symmetric sparse matrix: the ordering RENUM='METIS' (and 'AUTO' when some equation has no point: solver/CoordinateOrdering
// otherwise) hands to the factorisation.
// Independent of the solver: MUMPS takes the result as PERM_IN (ICNTL(7)=1), sequential or not.
#include <vector>

#include "solver/SparseMatrix.hpp"

namespace ma {

struct FillReducingOrdering {
    // pivotRank[i]: 0-based position of row/column i in the elimination order.
    std::vector<int> pivotRank;
    long long vertices = 0;    // of the graph METIS ordered: groups of consecutive rows of equal pattern
    long long graphEdges = 0;  // undirected edges between them
    double seconds = 0.0;      // graph + METIS
};

// The graph is that of the upper triangle of A (the entries the factorisation receives),
// symmetrised: every unknown of A is in it, multipliers and contact unknowns included;
// consecutive rows of identical pattern (a node's unknowns) are one vertex of their weight.
// Throws NumericalError when METIS fails (memory, or an internal error).
// `threads` >= 2 orders the two halves below the top separator in two processes (METIS 5.1's
// random generator is shared between threads: concurrent calls gave orderings that changed from
// run to run); the ordering does not depend on it.
FillReducingOrdering nestedDissectionOrdering(const CsrMatrix& A, int threads = 1);

}  // namespace ma
