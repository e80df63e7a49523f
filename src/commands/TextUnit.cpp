#include "commands/TextUnit.hpp"

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "core/AtomicFile.hpp"
#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "core/Mpi.hpp"

namespace ma {

namespace {
// Units written since the run started or since their last DEFI_FICHIER (their next write appends).
std::set<std::string>& openedThisRun() {
    static std::set<std::string> opened;
    return opened;
}
}  // namespace

void restartUnit(const std::string& path) { openedThisRun().erase(path); }

void appendToUnit(const std::string& command, const std::string& path, const std::string& text) {
    if (!mpi::isRoot()) return;  // rank 0 writes (docs/mpi.md)
    std::string content;
    if (openedThisRun().count(path) && std::filesystem::exists(path)) {
        std::ifstream in(path, std::ios::binary);
        if (!in) throw UserError(command + ": cannot read back " + path);
        std::ostringstream ss;
        ss << in.rdbuf();
        content = ss.str();
    }
    content += text;
    writeFileAtomically(path, content);
    openedThisRun().insert(path);
}

std::string printOnUnit(const std::string& command, long long unit, const Units* units, const std::string& text) {
    if (unit == 8) {
        msg().result(text);
        return "";
    }
    if (!units) throw UserError(command + ": no logical units are defined for this run");
    const std::string path = units->output(int(unit));
    appendToUnit(command, path, text);
    return path;
}

}  // namespace ma
