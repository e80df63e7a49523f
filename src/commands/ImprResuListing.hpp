#pragma once
// IMPR_RESU FORMAT='RESULTAT' of a result or a lone nodal field (ImprResuListing.cpp), called by
// IMPR_RESU's entry in ImprResu.cpp.
#include <string>

#include "parser/CommandRegistry.hpp"

namespace ma {

// The listing of one RESU occurrence with RESULTAT or CHAM_GD (post/NodalListing.hpp).
std::string resuListing(const KeywordSet& occ);

}  // namespace ma
