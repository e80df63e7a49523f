#pragma once
// POST_RELEVE_T, OPERATION='EXTRACTION' on nodal fields (commands_spec.md §2): one row per
// (action, order, node) with code_aster's columns in code_aster's order; with RESULTANTE one row per
// (action, order): the sum over the nodes of each component, and with MOMENT also the moment about
// POINT, in the columns RESULT_X/Y/Z, MOMENT_X/Y/Z (code_aster's rvpara / rvpsts).
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "fe/Result.hpp"
#include "post/Table.hpp"

namespace ma {

// One ACTION occurrence, with its field(s) already resolved.
struct NodalExtraction {
    std::string title;                    // INTITULE
    std::string keywordPath = "ACTION";   // the occurrence, for messages
    std::vector<std::string> nodes;       // NOEUD
    std::vector<std::string> nodeGroups;  // GROUP_NO
    // RESULTAT + NOM_CHAM: the steps to read, in the requested order ...
    std::shared_ptr<const Result> result;
    std::string fieldName;  // NOM_CHAM
    std::vector<const ResultStep*> steps;
    // ... or CHAM_GD.
    std::shared_ptr<const NodalField> field;
    bool allComponents = true;            // TOUT_CMP='OUI'
    std::vector<std::string> components;  // NOM_CMP, or RESULTANTE when `resultant`
    bool resultant = false;               // RESULTANTE: sums over the nodes
    bool moment = false;                  // MOMENT (with RESULTANTE): the moment about `point` too
    std::array<double, 3> point{};        // POINT (z = 0 when two values are given)
};

std::shared_ptr<Table> extractNodalValues(const std::vector<NodalExtraction>& actions);

}  // namespace ma
