#pragma once
// Reading meshes from MED files (LIRE_MAILLAGE), code_aster conventions (docs/med.md).
#include <memory>
#include <string>
#include <vector>

#include "mesh/Mesh.hpp"

namespace ma::med {

// What was read besides the mesh itself, for the command's log.
struct MeshReadReport {
    std::string meshName;  // name of the mesh inside the file
    int spaceDim = 0;
    int meshDim = 0;
    std::vector<std::string> meshesInFile;
    std::vector<std::pair<std::string, std::string>> renamedGroups;  // (name in file, name kept)
};

// Names of the meshes of a MED file, in file order. UserError when the file is missing or not MED.
std::vector<std::string> meshNames(const std::string& path);

// Reads the mesh `meshName` (empty: the first mesh of the file, as code_aster does).
// Nodes keep the file order; cells are numbered type by type in increasing MED type code;
// connectivity is converted to the internal node order; families become node and cell groups
// (names cut to 24 characters with an alarm). Names come from the file (first 8 characters) or
// are generated (N1..., M1...). Every error (missing file, not HDF5, damaged file, unknown mesh,
// unsupported cell kind) is a UserError or NotImplemented naming the file.
std::shared_ptr<Mesh> readMesh(const std::string& path, const std::string& meshName = {},
                               MeshReadReport* report = nullptr);

}  // namespace ma::med
