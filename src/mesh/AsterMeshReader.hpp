#pragma once
// Reading code_aster's native text mesh format (.mail, LIRE_MAILLAGE FORMAT='ASTER'); the format
// and the decisions taken where code_aster's behaviour is unsettled: docs/mesh.md.
#include <istream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/Message.hpp"
#include "mesh/Mesh.hpp"

namespace ma {

// What the reader found besides the mesh, for the command's log.
struct AsterMeshReport {
    std::vector<std::string> title;  // TITRE lines, verbatim
    // Empty groups left out, repeated group members dropped, group names cut to 24 characters
    // (src/mesh/MeshMessages.hpp), for the command to raise after its own lines.
    std::vector<FormattedMessage> alarms;
};

// Reads a .mail text. `source` names it in errors ("mesh file 'x.mail', line 12: ...").
// Nodes and cells keep file order (code_aster's numbering), the node order inside a cell is
// stored as written (it is code_aster's internal order, the one of Mesh). Every defect of the
// text is a UserError with its line.
std::shared_ptr<Mesh> parseAsterMesh(std::istream& in, const std::string& source, AsterMeshReport* report = nullptr);

// Same, from a file; UserError when it cannot be opened.
std::shared_ptr<Mesh> readAsterMesh(const std::string& path, AsterMeshReport* report = nullptr);

}  // namespace ma
