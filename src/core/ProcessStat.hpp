#pragma once
// /proc/PID/stat of any process of this machine, read with plain read(2): a process may end
// between the open and the read (ESRCH), which a std::ifstream reports by throwing.
#include <optional>
#include <string>

namespace ma {

// The fields after the command name (from field 3, the state, on), separated by spaces; nothing
// when the process does not exist (any more).
std::optional<std::string> processStatFields(int pid);

}  // namespace ma
