#pragma once
// Base of every object a command file manipulates (code_aster "concept"): a mesh, a model,
// a material, a load, a result, a table, a formula...
#include <memory>
#include <string>

namespace ma {

class Concept {
public:
    virtual ~Concept() = default;
    // code_aster type name, e.g. "maillage_sdaster", "evol_elas", "table_sdaster".
    virtual std::string typeName() const = 0;
    // User-visible name: the variable it was assigned to (`DEPZON[1]` -> "DEPZON_1"),
    // set by the supervisor after the command returns.
    std::string name;
};

using ConceptPtr = std::shared_ptr<Concept>;

}  // namespace ma
