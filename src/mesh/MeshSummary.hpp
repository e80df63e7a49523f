#pragma once
// The text code_aster prints after reading or changing a mesh (counts per cell type, groups with
// their sizes), and the checks of LIRE_MAILLAGE/VERI_MAIL.
#include <string>

#include "mesh/Mesh.hpp"

namespace ma {

std::string meshSummary(const Mesh& mesh, const std::string& meshName);

// VERI_MAIL: nodes used by no cell, cells with a repeated node. One line per finding kind.
std::vector<std::string> meshDefects(const Mesh& mesh);

}  // namespace ma
