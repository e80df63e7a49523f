#pragma once
// The text code_aster prints after reading or changing a mesh (counts per cell type, groups with
// their sizes), and the checks of LIRE_MAILLAGE/VERI_MAIL.
#include <string>
#include <vector>

#include "core/Message.hpp"
#include "mesh/Mesh.hpp"

namespace ma {

std::string meshSummary(const Mesh& mesh, const std::string& meshName);

// VERI_MAIL: nodes used by no cell, cells with a repeated node. One alarm per finding kind; `path`
// names the mesh file.
std::vector<FormattedMessage> meshDefects(const Mesh& mesh, const std::string& path);

}  // namespace ma
