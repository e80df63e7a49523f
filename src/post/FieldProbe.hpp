#pragma once
// The value TEST_RESU reads in a field (tresu_champ_no, tresu_champ_val, tresu_champ_all,
// tresu_champ_cmp): one component at a node or at an integration point, or MIN / MAX / SOMM /
// SOMM_ABS over the whole field. Errors name `where` (the keyword path) and the missing entity.
#include <optional>
#include <string>

#include "fields/Fields.hpp"
#include "post/TestCheck.hpp"

namespace ma {

// Component `component` at node `node` (the node must carry it: X-FEM enrichments only exist on
// the enriched nodes).
double nodalValue(const NodalField& field, int node, const std::string& component, const std::string& where);

// Component `component` at the `point`-th (1-based) integration point of the element on mesh cell
// `cell`; an X-FEM element numbers the points of its sub-cells one after the other.
double gaussValue(const GaussField& field, int cell, int point, const std::string& component, const std::string& where);

// The reduction over every value the field holds (nodal: the components each node carries), or over
// one component's values when `component` is given.
double reduceField(const NodalField& field, Reduction reduction, const std::optional<std::string>& component,
                   const std::string& where);
double reduceField(const GaussField& field, Reduction reduction, const std::optional<std::string>& component,
                   const std::string& where);

}  // namespace ma
