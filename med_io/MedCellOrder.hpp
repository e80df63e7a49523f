#pragma once
// Node order of each cell type in MED and in code_aster (internal) numbering.
// The tables follow code_aster's lrmtyp (NUMNOA): internal node j is MED node medNodeOf[j].
// They are NOT all involutions (HEXA20/27, PENTA15/18 differ in both directions), so readers
// use medNodeOf and writers use its inverse. No MED header here: tests use these tables too.
#include <span>

#include "mesh/CellType.hpp"

namespace ma::med {

// 0-based: internal node j of a cell of type t is MED node medNodeOf(t)[j].
// Empty span when both orders are the same (segments, 2D cells, POI1).
std::span<const int> medNodeOf(CellType t);

// From a MED connectivity row (any node ids) to the internal row, and back.
void medToInternal(CellType t, std::span<const int> med, std::span<int> internal);
void internalToMed(CellType t, std::span<const int> internal, std::span<int> med);

}  // namespace ma::med
