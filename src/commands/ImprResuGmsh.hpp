#pragma once
// IMPR_RESU FORMAT='GMSH' (ImprResuGmsh.cpp), called by IMPR_RESU's entry in ImprResu.cpp.
#include "parser/CommandRegistry.hpp"

namespace ma {

ConceptPtr imprResuGmsh(const KeywordSet& kw, CommandContext& ctx);

}  // namespace ma
