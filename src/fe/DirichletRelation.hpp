#pragma once
// A Dirichlet condition as the engine imposes it: a linear relation
//     sum_i coef_i * u(node_i, component_i) = value,
// and the DDL_IMPO request (one component of one occurrence) that the load expands into them.
#include <memory>
#include <string>
#include <vector>

#include "core/Function.hpp"

namespace ma {

struct DofTerm {
    int node = -1;
    std::string component;  // "DX", "H1Y" ...
    double coef = 1.0;
};

struct LinearRelation {
    std::vector<DofTerm> terms;
    double value = 0.0;
};

// One component of one DDL_IMPO occurrence: value given as a real or as a function of
// X, Y, Z, INST (evaluated at the nodes, in one batch).
struct ImposedDof {
    std::string path;        // "DDL_IMPO[2]/DX", for messages
    std::vector<int> nodes;  // nodes of the occurrence (all of them; the enrichment filters)
    std::string component;
    double value = 0.0;
    std::shared_ptr<const Function> function;  // null: constant value
};

}  // namespace ma
