#pragma once
// A node-local change of unknowns u = T v for algebraic multigrid on X-FEM models (docs/solver.md,
// "The piece basis"). At an X-FEM node the enriched shape functions take one independent value in
// each piece of its support; v holds these values (one copy of the node per piece, `dim` unknowns
// each, a component the Dirichlet conditions eliminate left as a padding unknown), so T^T K T is a
// classical finite element matrix on the copies and the rigid motions of every block are the
// model's rigid modes evaluated at the copies. The operator then needs 6 (3D) or 3 (2D) near-null
// vectors, not the 6 of each colour of blocks.
#include <span>
#include <string>
#include <vector>

#include "solver/SparseMatrix.hpp"

namespace ma {

struct PieceBasis {
    int copies = 0;                   // v has blockSize * copies unknowns, copy after copy
    int blockSize = 3;                // the dimension: the unknowns of one copy
    int blocks = 0;                   // blocks of the model (for the .mess)
    CsrMatrix T;                      // free equations x v unknowns: u_i = sum_k T_ik v_k
    std::vector<char> padding;        // per v unknown: no free equation depends on it
    std::vector<double> modes;        // the rigid modes on v, vector after vector (0 on padding)
    std::vector<double> coordinates;  // per copy, its node's blockSize coordinates
    std::string refusal;              // why there is no piece basis (copies == 0)

    int size() const { return blockSize * copies; }
};

// T^T A T on the v unknowns, with 1 on the padding unknowns' diagonal. Entries below
// dropTolerance * sqrt(|a_kk a_ll|) are left out (the round-off of couplings between disjoint pieces,
// which cancel exactly; 0 keeps every computed entry).
CsrMatrix pieceBasisMatrix(const CsrMatrix& A, const PieceBasis& basis, double dropTolerance);

// One process's share of the piece basis on several processes (docs/solver.md, "The piece basis on
// several processes"): the copies [copyBegin, copyEnd) and the equations that read them, and no other
// copy (sorted).
struct PieceShare {
    int copyBegin = 0, copyEnd = 0;
    std::vector<int> equations;

    int unknowns(int blockSize) const { return blockSize * (copyEnd - copyBegin); }
};

// The share's part of T^T A T when shareRows holds the rows share.equations of A (with global
// columns): |its diagonal|, then its rows (global columns, the drop test of pieceBasisMatrix against
// the whole diagonal).
std::vector<double> pieceBasisDiagonal(const CsrMatrix& shareRows, const PieceShare& share, const PieceBasis& basis);
CsrMatrix pieceBasisRows(const CsrMatrix& shareRows, const PieceShare& share, const PieceBasis& basis,
                         std::span<const double> diagonal, double dropTolerance);

// v -> u (u = T v) and u -> v (w = T^T r).
void toEquations(const PieceBasis& basis, const double* v, double* u);
void toPieces(const PieceBasis& basis, const double* r, double* w);
// The share's w = T^T r from its equations' r (r[k] is equation share.equations[k], w[0] unknown
// blockSize * copyBegin).
void toPieces(const PieceBasis& basis, const PieceShare& share, const double* r, double* w);

}  // namespace ma
