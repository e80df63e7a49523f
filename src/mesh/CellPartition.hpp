#pragma once
// The cells of a model dealt to the processes of a run (docs/mpi.md): METIS_PartMeshDual on the
// dual graph of the cells (two cells are neighbours when they share a face: `dim` nodes, dim the cells' dimension), each cell
// weighted by its cost (e.g. its integration points, so that X-FEM cells count for their
// sub-cells). Deterministic: METIS's fixed seed, the same partition on every process and run.
#include <span>
#include <vector>

#include "mesh/Mesh.hpp"

namespace ma {

// owner[i] in [0, parts) for cells[i]. parts == 1: all 0; fewer cells than parts: cell i to i.
// NumericalError when METIS fails.
std::vector<int> partitionCells(const Mesh& mesh, std::span<const int> cells, std::span<const int> weights, int dim,
                                int parts);

}  // namespace ma
