#pragma once
// Internal forces F_int(u) = sum_e int B^T sigma(u) of a mechanical problem, in dof order. Element
// vectors are computed on the workers and added in element order by the worker owning each block
// of 64 dofs: the sums of the serial loop, bit for bit. Distributed (docs/mpi.md): each process
// computes its own elements and the vectors are summed over the processes (every one gets F_int).
#include <vector>

#include "fe/Discretisation.hpp"

namespace ma {

class PointWriter;

// f: numbering().size() entries (u may have more: the additional terms' unknowns are not read).
// With `cells` (a flag per mesh cell), only the elements of the flagged cells contribute. With
// `points`, every point of the elements this process computes is written by it (SIEF_ELGA from
// the same loop: fe/ResultFields.hpp PointFieldRecording).
void assembleInternalForces(const Discretisation& space, const std::vector<double>& u, std::vector<double>& f,
                            const std::vector<char>* cells = nullptr, PointWriter* points = nullptr);

}  // namespace ma
