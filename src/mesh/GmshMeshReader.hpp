#pragma once
// Reading a gmsh mesh (LIRE_MAILLAGE FORMAT='GMSH'): MSH 2 text files, turned into the mesh
// code_aster's PRE_GMSH makes of them (docs/mesh.md "GMSH meshes"): nodes N<number> (those no
// element uses left out), cells M<number> grouped by gmsh element type, one cell group GM<tag>
// per physical tag (and a node group of the same name for a group that is one point element).
#include <istream>
#include <memory>
#include <string>

#include "mesh/Mesh.hpp"

namespace ma {

// `source` names the text in errors ("mesh file 'x.msh', line 12: ..."). Every defect is a
// UserError with its line: another format version, binary files, unknown element types, elements
// naming absent nodes, numbers used twice, elements without a physical tag.
std::shared_ptr<Mesh> parseGmshMesh(std::istream& in, const std::string& source);

// Same, from a file; UserError when it cannot be opened.
std::shared_ptr<Mesh> readGmshMesh(const std::string& path);

}  // namespace ma
