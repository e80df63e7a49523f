#include "parser/ExportFile.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "core/AtomicFile.hpp"

namespace fs = std::filesystem;

namespace ma {

const char* const kNotRegular = "a FIFO, a device or a socket: its reading could wait for ever";

namespace {

// Units are Fortran logical units in code_aster: 1..99, 0 for entries without one.
constexpr int kMaxUnit = 99;
constexpr int kCodeUnit = 15;  // reserved for the 'code' file (run_aster/export.py)

std::vector<std::string> tokens(const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> t;
    for (std::string w; in >> w;) t.push_back(w);
    return t;
}

// The whole text is a number (no sign, no trailing characters): `80abc`, `-80`, `8.0` are not.
std::optional<int> parseUnit(const std::string& text) {
    int value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size() || text[0] == '-' || text[0] == '+') return std::nullopt;
    return value;
}

std::optional<double> parsePositive(const std::string& text) {
    double value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value) || value <= 0)
        return std::nullopt;
    return value;
}

class Reader {
public:
    Reader(const std::string& exportPath, const std::optional<fs::path>& resultBase)
        : folder_(fs::absolute(exportPath).parent_path()),
          resultBase_(resultBase ? fs::absolute(*resultBase) : folder_) {
        out_.name = fs::path(exportPath).filename().string();
    }

    ExportFile read(std::istream& in) {
        std::string text;
        while (std::getline(in, text)) {
            ++line_;
            if (line_ == 1 && text.starts_with("\xEF\xBB\xBF")) text.erase(0, 3);  // a UTF-8 byte order mark
            texts_.push_back(text);
            const auto t = tokens(text);
            if (t.empty() || t[0][0] == '#') continue;
            if (t[0] == "P") parameter(t);
            else if (t[0] == "A") continue;  // arguments of the command file: nothing to set up
            else if (t[0] == "F" || t[0] == "R") entry(t);
            else fail(fmt::format("unknown line type '{}' (expected P, A, F or R)", t[0]));
        }
        checkConsistency();
        return std::move(out_);
    }

private:
    [[noreturn]] void fail(const std::string& cause) const {
        throw ExportError(fmt::format("{}, line {}: {} ({})", out_.name, line_, cause, texts_[size_t(line_ - 1)]));
    }

    void parameter(const std::vector<std::string>& t) {
        if (t.size() < 2) fail("a P line needs a name");
        const std::string& name = t[1];
        if (!parameterLines_.emplace(name, line_).second)
            fail(fmt::format("parameter '{}' is already given on line {}", name, parameterLines_[name]));
        if (name == "time_limit" || name == "memory_limit") {
            if (t.size() != 3) fail(fmt::format("'{}' needs one value", name));
            const auto value = parsePositive(t[2]);
            if (!value)
                fail(fmt::format("'{}' must be a positive number ({}), got '{}'", name,
                                 name == "time_limit" ? "seconds" : "megabytes", t[2]));
            (name == "time_limit" ? out_.timeLimitSeconds : out_.memoryLimitMb) = *value;
        } else if (name == "mpi_nbcpu") {
            const auto value = t.size() == 3 ? parseUnit(t[2]) : std::nullopt;
            if (!value || *value < 1 || *value > kMaxProcesses)
                fail(fmt::format("'mpi_nbcpu' must be a number of processes from 1 to {}", kMaxProcesses));
            out_.mpiProcesses = *value;
        }
    }

    void entry(const std::vector<std::string>& t) {
        if (t.size() < 5) fail(fmt::format("expected `{} <type> <path> <flags> <unit>`", t[0]));
        ExportEntry e;
        e.line = line_;
        e.directory = t[0] == "R";
        e.type = t[1];
        std::string path = t[2];  // a path with blanks (run_aster joins the middle fields)
        for (size_t k = 3; k + 2 < t.size(); ++k) path += " " + t[k];
        const std::string& flags = t[t.size() - 2];
        const auto unit = parseUnit(t.back());
        if (!unit || *unit > kMaxUnit)
            fail(fmt::format("the unit '{}' is not a logical unit (an integer 0..{})", t.back(), kMaxUnit));
        e.unit = *unit;
        for (char c : flags) {
            bool& flag = c == 'D' ? e.data : c == 'R' ? e.result : c == 'C' ? e.compressed : bad_;
            if (&flag == &bad_)
                fail(fmt::format("unknown flag '{}' in '{}' (D data, R result, C compressed)", c, flags));
            if (flag) fail(fmt::format("flag '{}' repeated in '{}'", c, flags));
            flag = true;
        }
        if (!e.data && !e.result) fail(fmt::format("the flags '{}' say neither D (data) nor R (result)", flags));
        if (e.directory && e.compressed) fail("a directory (R line) cannot be compressed");
        if (e.type == "base" || e.type == "bhdf")
            fail(
                fmt::format("'{}' is a code_aster database: miniaster neither reads nor writes one (there is "
                            "no POURSUITE); remove the line",
                            e.type));
        if (e.unit == kCodeUnit && e.type != "code")
            fail(fmt::format("unit {} is reserved for the 'code' file", kCodeUnit));
        if (e.data && e.result && e.compressed) fail("a compressed file is either data (DC) or result (RC), not both");
        if (e.type == "comm" && !e.data) fail("the command file must be data (D)");
        if (e.unit > 0) {
            auto [it, added] = unitLines_.emplace(e.unit, line_);
            if (!added) fail(fmt::format("unit {} is already given on line {}", e.unit, it->second));
        }
        const fs::path given = path;
        e.path =
            fs::absolute(given.is_relative() ? (e.data ? folder_ : resultBase_) / given : given).lexically_normal();
        if (e.data) checkData(e);
        out_.entries.push_back(std::move(e));
    }

    void checkData(const ExportEntry& e) const {
        std::error_code ec;
        const auto status = fs::status(e.path, ec);
        if (!fs::exists(status))
            fail(fmt::format("the data {} {}{} does not exist", e.directory ? "directory" : "file", e.path.string(),
                             e.unit > 0 ? fmt::format(" of unit {}", e.unit) : ""));
        if (e.directory && !fs::is_directory(status)) fail(fmt::format("{} is not a directory", e.path.string()));
        if (!e.directory && fs::is_directory(status))
            fail(fmt::format("{} is a directory, not a file (directories go on R lines)", e.path.string()));
        if (!e.directory && !fs::is_regular_file(status))
            fail(fmt::format("{} is not a regular file ({})", e.path.string(), kNotRegular));
    }

    void checkConsistency() {
        int comms = 0;
        std::map<fs::path, int> dataLines;
        for (const auto& e : out_.entries)
            if (e.data) dataLines.emplace(e.path, e.line);
        for (const auto& e : out_.entries) {
            if (e.type == "comm") ++comms;
            if (e.type == "comm" && comms > 1) {
                line_ = e.line;
                fail("several command files; miniaster runs one");
            }
            if (!e.result || e.data) continue;
            auto it = dataLines.find(e.path);
            if (it != dataLines.end()) {
                line_ = e.line;
                fail(fmt::format("the result {} is the data file of line {}: the run would overwrite its own input",
                                 e.path.string(), it->second));
            }
        }
        if (comms == 0) throw ExportError(out_.name + ": no command file (`F comm <file> D 1`)");
    }

    fs::path folder_, resultBase_;
    ExportFile out_;
    int line_ = 0;
    std::vector<std::string> texts_;  // every line read, for the messages
    bool bad_ = false;                // target of an unknown flag (never set)
    std::map<std::string, int> parameterLines_;
    std::map<int, int> unitLines_;
};

}  // namespace

std::string ExportFile::where(const ExportEntry& e) const { return fmt::format("{}, line {}", name, e.line); }

ExportFile readExportFile(const std::string& exportPath, const std::optional<fs::path>& resultBase) {
    std::error_code ec;
    if (fs::is_directory(exportPath, ec)) throw ExportError("the .export file " + exportPath + " is a directory");
    if (fs::exists(exportPath, ec) && !fs::is_regular_file(exportPath, ec))
        throw ExportError("the .export file " + exportPath + " is not a regular file (" + kNotRegular + ")");
    std::ifstream in(exportPath);
    if (!in) throw ExportError(systemError("cannot read the .export file", exportPath, errno));
    return Reader(exportPath, resultBase).read(in);
}

}  // namespace ma
