#pragma once
// The check of the whole command file before its first command runs (docs/supervisor.md,
// "Static check"): every call the catalog can see in the Python syntax tree — unknown names called
// like commands, commands miniaster does not provide, keywords and _F keywords that are not in
// the catalog — reported at once with their lines. Calls it cannot see statically (**kwargs,
// commands called through variables, names defined in the file, exec/eval, star imports) are left
// to the run: a valid file is never refused.
#include <string>

namespace ma {

class RunState;

// `source`: the command file's bytes. Returns false (the failure recorded in `run`, nothing run)
// when a problem was found. Needs the interpreter.
bool checkCommandFileStatically(const std::string& source, RunState& run);

}  // namespace ma
