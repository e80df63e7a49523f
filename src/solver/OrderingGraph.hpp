#pragma once
// The graph a fill-reducing ordering works on, shared by the METIS and the coordinate orderings:
// consecutive rows of A with the same pattern (the unknowns of one node) form one vertex, weighted
// by their number; edges are those of the upper triangle of A (the entries the factorisation
// receives), symmetrised. A 2D node graph has a quarter of the edges of the dof graph, and the
// elimination order of the rows follows from that of their vertices.
#include <metis.h>

#include <vector>

#include "solver/SparseMatrix.hpp"

namespace ma {

struct Supervariables {
    std::vector<int> of;      // row -> supervariable
    std::vector<idx_t> size;  // supervariable -> rows
};

struct OrderingGraph {
    std::vector<idx_t> start, neighbours;  // compressed adjacency, no loops, no repeats
};

Supervariables consecutiveIdenticalRows(const CsrMatrix& A);
OrderingGraph supervariableGraph(const CsrMatrix& A, const Supervariables& s);

// Row pivot ranks from the elimination rank of each supervariable: the rows of a supervariable
// take consecutive ranks, in the supervariables' order.
std::vector<int> rowRanks(const Supervariables& s, const std::vector<idx_t>& rankOfVertex);

}  // namespace ma
