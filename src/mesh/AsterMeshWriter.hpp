#pragma once
// Writing a mesh in code_aster's text format (.mail): what IMPR_RESU FORMAT='RESULTAT' or 'ASTER'
// prints for RESU/MAILLAGE, laid out as code_aster's irmare writes it (list-directed keywords
// with a leading blank, names as A8, coordinates as 1PE21.14, 7 nodes per line), so that
// LIRE_MAILLAGE FORMAT='ASTER' (code_aster's or miniaster's) reads it back.
#include <string>
#include <vector>

#include "mesh/Mesh.hpp"

namespace ma {

// The whole text, from TITRE to FIN. `title`: the TITRE lines.
std::string asterMeshText(const Mesh& mesh, const std::vector<std::string>& title);

}  // namespace ma
