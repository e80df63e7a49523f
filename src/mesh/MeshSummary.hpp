#pragma once
// The text code_aster prints after reading or changing a mesh (counts per cell type, groups with
// their sizes).
#include <string>

#include "mesh/Mesh.hpp"

namespace ma {

std::string meshSummary(const Mesh& mesh, const std::string& meshName);

}  // namespace ma
