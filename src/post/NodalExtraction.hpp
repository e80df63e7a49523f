#pragma once
// POST_RELEVE_T, OPERATION='EXTRACTION' on nodal fields (commands_spec.md §2): one row per
// (action, order, node) with code_aster's columns in code_aster's order.
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
    std::vector<std::string> components;  // NOM_CMP
};

std::shared_ptr<Table> extractNodalValues(const std::vector<NodalExtraction>& actions);

}  // namespace ma
