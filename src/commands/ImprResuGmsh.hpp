#pragma once
// IMPR_RESU FORMAT='GMSH' (ImprResuGmsh.cpp), called by IMPR_RESU's entry in ImprResu.cpp.
#include <vector>

#include "fe/Result.hpp"
#include "parser/CommandRegistry.hpp"

namespace ma {

ConceptPtr imprResuGmsh(const KeywordSet& kw, CommandContext& ctx);

// The steps a RESU occurrence selects (NUME_ORDRE, INST with CRITERE/PRECISION, else all);
// defined in ImprResu.cpp, used by both formats.
std::vector<const ResultStep*> selectedResultSteps(const Result& result, const KeywordSet& occ);

}  // namespace ma
