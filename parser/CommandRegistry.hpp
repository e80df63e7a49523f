#pragma once
// Commands are plain C++ functions: keyword tree in, concept out. Each file of src/commands
// registers its command(s) with MA_REGISTER_COMMAND; the supervisor dispatches to them after
// checking the call against the catalog (parser/Catalog*).
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "core/Concept.hpp"
#include "parser/KeywordTree.hpp"

namespace ma {

class Units;

struct CommandContext {
    std::string command;     // e.g. "LIRE_MAILLAGE"
    std::string resultName;  // variable the result is assigned to ("" when not assigned)
    ConceptPtr reused;       // object given by reuse=, or null
    std::string commFile;    // .comm path, for messages
    int line = 0;            // .comm line of the call
    Units* units = nullptr;  // logical units of the run (.export F lines)
    int info = 1;            // INFO keyword when present, else 1
    // Expert run options given on the command line (parser/RunOptions.hpp): name -> value, as
    // typed; already checked by the option's own check.
    std::map<std::string, std::string> runOptions;
};

using CommandFunction = std::function<ConceptPtr(const KeywordSet&, CommandContext&)>;

class CommandRegistry {
public:
    static CommandRegistry& instance();
    void add(const std::string& name, CommandFunction fn);
    const CommandFunction* find(const std::string& name) const;
    std::vector<std::string> names() const;  // every registered command, sorted

private:
    std::map<std::string, CommandFunction> commands_;
};

struct CommandRegistration {
    CommandRegistration(const char* name, CommandFunction fn) { CommandRegistry::instance().add(name, std::move(fn)); }
};

#define MA_CONCAT_INNER(a, b) a##b
#define MA_CONCAT(a, b) MA_CONCAT_INNER(a, b)
// Usage, at namespace scope in a src/commands/*.cpp file:
//   MA_REGISTER_COMMAND("LIRE_MAILLAGE", lireMaillage);
#define MA_REGISTER_COMMAND(NAME, FN) \
    static ::ma::CommandRegistration MA_CONCAT(ma_command_registration_, __LINE__)(NAME, FN)

}  // namespace ma
