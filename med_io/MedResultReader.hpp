#pragma once
// Reading result files back (miniaster convert / plot): every mesh of a MED file with the fields
// defined on it, at every computation step (docs/med.md, "Reading results back").
#include <memory>
#include <string>
#include <vector>

#include "fields/Fields.hpp"
#include "mesh/Mesh.hpp"

namespace ma::med {

// One computation step of a field: a nodal field (MED_NODE) or values at the points of each cell
// (MED_CELL: ELGA, MED_NODE_ELEMENT: ELNO, both kept as a GaussField whose elements are cells).
struct MedFieldStep {
    int numdt = -1, numit = -1;
    double dt = 0.0;
    std::shared_ptr<NodalField> nodal;
    std::shared_ptr<GaussField> cellPoints;
};

struct MedField {
    std::string name;  // the name in the file, e.g. RES_XFEMDEPL
    std::vector<std::string> components;
    std::vector<MedFieldStep> steps;  // in file order (increasing numdt, numit)
};

struct MedResultMesh {
    std::string name;
    std::shared_ptr<Mesh> mesh;  // as LIRE_MAILLAGE reads it (internal node order, groups)
    std::vector<MedField> fields;
};

// Every mesh of the file, in file order, with its real-valued fields (MED_FLOAT64/32; other
// value types, and steps whose values cannot be read, give a UserError naming field and step).
// Profiles are resolved: a node or cell outside a field's profiles is absent from that step.
std::vector<MedResultMesh> readResults(const std::string& path);

}  // namespace ma::med
