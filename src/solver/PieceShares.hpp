#pragma once
// How the piece basis is shared between processes (solver/PiecesOnProcesses.hpp; docs/solver.md,
// "The piece basis on several processes").
#include <vector>

#include "solver/PieceBasis.hpp"

namespace ma {

// Shares for `processes` processes by recursive coordinate bisection of the nodes (the groups of
// copies and equations that read one another), each cut across the longest extent of its part, so
// that a plate or a slab is never cut through its thickness, where the couplings are strongest.
// The copies are renumbered share after share (T, padding, modes and coordinates follow). Empty
// (the basis unchanged) when there are fewer nodes than processes.
std::vector<PieceShare> shareByCoordinates(PieceBasis& basis, int processes);

}  // namespace ma
