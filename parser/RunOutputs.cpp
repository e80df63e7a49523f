#include "parser/RunOutputs.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>
#include <zlib.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <set>
#include <thread>

#include "core/AtomicFile.hpp"
#include "core/Error.hpp"
#include "core/Messages.hpp"
#include "core/Mpi.hpp"
#include "core/TestReport.hpp"
#include "parser/OutputGuard.hpp"
#include "parser/RunState.hpp"

namespace fs = std::filesystem;

namespace ma {

namespace {

// ---- gzip (.export flag C)

std::string stripGz(const fs::path& p) {
    std::string name = p.filename().string();
    if (name.size() > 3 && name.ends_with(".gz")) name.resize(name.size() - 3);
    return name;
}

void gunzipTo(const std::string& source, const std::string& target) {
    gzFile in = gzopen(source.c_str(), "rb");
    if (!in) throw UserError(systemError("cannot read the compressed data file", source, errno));
    const int fd = ::open(target.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) {
        gzclose_r(in);
        throw UserError(systemError("cannot create", target, errno));
    }
    std::string failure;
    if (gzdirect(in)) failure = "the data file " + source + " (flag C) is not gzip-compressed";
    char buffer[1 << 16];
    for (int n = 0; failure.empty() && (n = gzread(in, buffer, sizeof(buffer))) != 0;) {
        if (n < 0) {
            failure = "the compressed data file " + source + " is damaged or truncated (gzip)";
        } else if (::write(fd, buffer, size_t(n)) != n) {
            failure = systemError("cannot write", target, errno);
        }
    }
    if (failure.empty() && gzclose_r(in) != Z_OK) failure = "the compressed data file " + source + " is damaged (gzip)";
    ::close(fd);
    if (!failure.empty()) throw UserError(failure);
}

// Compresses `source` (a file) or `text` into `target` atomically.
void gzipTo(const std::string& target, const std::string* source, const std::string* text) {
    AtomicPath out(target);
    gzFile gz = gzopen(out.tempPath().c_str(), "wb");
    if (!gz) throw UserError(systemError("cannot create", out.tempPath(), errno));
    bool ok = true;
    if (text) {
        ok = text->empty() || gzwrite(gz, text->data(), unsigned(text->size())) == int(text->size());
    } else {
        FILE* in = std::fopen(source->c_str(), "rb");
        ok = in != nullptr;
        char buffer[1 << 16];
        for (size_t n; ok && in && (n = std::fread(buffer, 1, sizeof(buffer), in)) > 0;)
            ok = gzwrite(gz, buffer, unsigned(n)) == int(n);
        if (in) std::fclose(in);
    }
    const int error = errno;
    if (gzclose_w(gz) != Z_OK || !ok) throw UserError(systemError("cannot write", out.tempPath(), error ? error : EIO));
    out.commit();
}

std::string& scratchFolder(RunOutputs& out) {
    if (out.scratch.empty()) {
        std::error_code ec;
        fs::create_directories(out.outDir, ec);
        const std::string folder = temporaryPathFor((fs::path(out.outDir) / "export-files").string());
        registerTemporary(folder);
        if (!fs::create_directory(folder, ec) || ec)
            throw UserError("cannot create the scratch folder " + folder + ": " + ec.message());
        out.scratch = folder;
    }
    return out.scratch;
}

// ---- checks

// The folder exists (created if needed) and a file can be created in it.
void checkWritableFolder(const fs::path& folder, const std::string& role) {
    std::error_code ec;
    if (fs::exists(folder, ec) && !fs::is_directory(folder, ec))
        throw UserError(fmt::format("the {} {} is not a folder (a file of that name exists)", role, folder.string()));
    fs::create_directories(folder, ec);
    if (ec) throw UserError(fmt::format("cannot create the {} {}: {}", role, folder.string(), ec.message()));
    const std::string probe = temporaryPathFor((folder / "write-check").string());
    const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    if (fd < 0) throw UserError(systemError(fmt::format("cannot write in the {}", role), folder.string(), errno));
    ::close(fd);
    ::unlink(probe.c_str());
}

void writeResultFile(const RunOutputs& out, const std::string& text) {
    if (out.resuCompressed) gzipTo(out.resu, nullptr, &text);
    else writeFileAtomically(out.resu, text);
}

void reportOnStderr(const std::string& text) { std::fprintf(stderr, "miniaster: %s\n", text.c_str()); }

}  // namespace

void applyExport(const ExportFile& exportFile, RunState& run, RunOutputs& out) {
    for (const auto& e : exportFile.entries) {
        const std::string path = e.path.string();
        if (e.directory) {
            if (e.result && !out.resultFolders.empty())
                throw UserError(exportFile.where(e) +
                                ": a second result directory; miniaster writes the units "
                                "without an F line into one (the first R line)");
            if (e.result) out.resultFolders.push_back(path);
            continue;
        }
        if (e.data) {
            std::string input = path;
            if (e.compressed) {
                input = (fs::path(scratchFolder(out)) / stripGz(e.path)).string();
                gunzipTo(path, input);
            }
            if (e.type == "comm") run.commFile = input;
            else if (e.unit > 0) run.units.setInput(e.unit, input);
        }
        if (!e.result) continue;
        out.resultFiles.push_back(path);
        if (e.type == "mess") {
            if (e.compressed)
                throw UserError(exportFile.where(e) +
                                ": the message log is written as the run goes: it cannot be "
                                "compressed (flag C)");
            out.mess = path;
        } else if (e.type == "resu") {
            out.resu = path;
            out.resuCompressed = e.compressed;
        } else if (e.unit > 0 && e.compressed) {
            const std::string plain = (fs::path(scratchFolder(out)) / stripGz(e.path)).string();
            run.units.setOutput(e.unit, plain);
            out.compressedResults.push_back({plain, path});
        } else if (e.unit > 0) {
            run.units.setOutput(e.unit, path);
        }
    }
}

// The files the run writes: the .mess, the .resu and every result unit (a compressed one by its
// final path).
std::vector<NamedPath> outputPaths(const RunOutputs& out, const Units& units) {
    std::vector<NamedPath> paths = {{out.mess, "message log"}, {out.resu, "result file"}};
    for (const auto& [unit, path] : units.outputs()) {
        std::string written = path;
        for (const auto& c : out.compressedResults)
            if (c.plain == path) written = c.final;
        paths.push_back({written, fmt::format("result file of unit {}", unit)});
    }
    return paths;
}

void prepareOutputs(RunOutputs& out, const RunState& run, const std::string& exportFile) {
    std::vector<NamedPath> inputs = {{run.commFile, "command file"}, {exportFile, ".export file"}};
    for (const auto& [unit, path] : run.units.inputs())
        inputs.push_back({path, fmt::format("data file of unit {}", unit)});
    checkOutputPaths(outputPaths(out, run.units), inputs);
    std::set<fs::path> folders;
    checkWritableFolder(out.outDir, "output folder");
    folders.insert(out.outDir);
    for (const auto& f : out.resultFolders) {
        checkWritableFolder(f, "result directory");
        folders.insert(f);
    }
    std::vector<std::string> files = out.resultFiles;
    files.push_back(out.mess);
    files.push_back(out.resu);
    for (const auto& file : files) {
        std::error_code ec;
        if (fs::is_directory(file, ec)) throw UserError("the result file " + file + " is a folder");
        const fs::path folder = fs::path(file).parent_path();
        if (folders.insert(folder).second) checkWritableFolder(folder, "folder of the result file " + file + ",");
    }
    for (const auto& folder : folders)
        for (const auto& name : removeStaleTemporaries(folder.string()))
            msg().info(fmt::format("  removed {} (a temporary file of a run that no longer exists)",
                                   (folder / name).string()));
}

void openMessageLog(RunOutputs& out) {
    out.messFd = openLockedMessageLog(out.mess);
    msg().streamTo(out.messFd, out.mess);
}

bool finishOutputs(RunOutputs& out, bool failed, bool checkOnly) {
    bool ok = true;
    const std::string& text = msg().resuText();
    std::error_code ec;
    if (msg().streamError()) {
        // The log is incomplete: a result file beside it would look like a finished run.
        reportOnStderr(systemError("cannot write the message log", out.mess, msg().streamError()) +
                       "; no result file written");
        ok = false;
    } else if (!checkOnly && (!failed || !text.empty())) {
        try {
            writeResultFile(out, text);
        } catch (const UserError& e) {
            msg().info(std::string("\n<F> <ERROR> ") + e.what());
            reportOnStderr(e.what());
            ok = false;
        }
    } else if (failed && fs::exists(out.resu, ec)) {
        msg().info("  (no result file written: " + out.resu + " is not from this run and is left as it was)");
    }
    for (const auto& c : out.compressedResults) {
        if (!fs::exists(c.plain, ec)) continue;
        try {
            gzipTo(c.final, &c.plain, nullptr);
        } catch (const UserError& e) {
            msg().info(std::string("\n<F> <ERROR> ") + e.what());
            reportOnStderr(e.what());
            ok = false;
        }
    }
    if (!out.scratch.empty()) {
        fs::remove_all(out.scratch, ec);
        forgetTemporary(out.scratch);
    }
    if (out.messFd >= 0) {
        // The log's descriptor now (reopened if the command file closed it: core/Messages.hpp).
        const int fd = msg().streamFd();
        if (!msg().streamError() && ::fsync(fd) != 0 && errno != EINVAL) ok = false;
        msg().streamTo(-1);
        if (::close(fd) != 0) ok = false;
        out.messFd = -1;
        if (ok && msg().streamError()) {
            reportOnStderr(systemError("cannot write the message log", out.mess, msg().streamError()));
            ok = false;
        }
    }
    return ok;
}

namespace {

// What an emergency stop appends to the log: the paragraph, the TEST lines' summary, the diagnostic.
std::vector<std::string> emergencyEnd(const std::string& paragraph, const std::string& diagnostic) {
    std::vector<std::string> pieces = {"\n" + paragraph + "\n"};
    const auto& tests = testReport();
    if (!tests.empty()) pieces.push_back(fmt::format("\n{}", tests.summary()));
    const std::string rule(60, '-');
    pieces.push_back(fmt::format("\n{}\n--- DIAGNOSTIC JOB : {}\n{}", rule, diagnostic, rule));
    return pieces;
}

// Whether the log already ends with a diagnostic (rank 0 stopped by a signal or a limit, then ended).
bool endsWithDiagnostic(const std::string& mess) {
    const int fd = ::open(mess.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return true;  // nothing to complete
    char tail[256] = {};
    const off_t size = ::lseek(fd, 0, SEEK_END);
    const ssize_t n = ::pread(fd, tail, sizeof(tail) - 1, std::max<off_t>(0, size - off_t(sizeof(tail) - 1)));
    ::close(fd);
    return n > 0 && std::string(tail, size_t(n)).find("--- DIAGNOSTIC JOB : ") != std::string::npos;
}

// A process other than rank 0 writes nothing. The time limit and the signals reach every process
// within a moment: it waits a little, so that rank 0 (whose end makes mpirun end the others)
// writes its paragraph, instead of ending first and making mpirun abort rank 0 unannounced. A
// memory limit may be this process's alone: its cause goes to stderr (mpirun forwards it). Rank 0
// ended without a word (the only ERROR of a watchdog on another process, parser/PeerWatch): rank
// 1 appends the end of the log to rank 0's .mess, unless rank 0 wrote its own end first.
[[noreturn]] void stopOtherProcessNow(const RunOutputs& out, const std::string& paragraph,
                                      const std::string& diagnostic) {
    if (diagnostic == "<F>_MEMORY_LIMIT")
        std::fprintf(stderr, "miniaster: MPI process %d of %d: %s\n", mpi::rank(), mpi::size(), paragraph.c_str());
    if (diagnostic == "<F>_ERROR" && !out.mess.empty() && !endsWithDiagnostic(out.mess)) {
        std::string text = "\n";  // rank 0 may have ended mid-line
        for (auto piece : emergencyEnd(paragraph, diagnostic)) text += piece.back() == '\n' ? piece : piece + "\n";
        if (const int fd = ::open(out.mess.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC); fd >= 0) {
            [[maybe_unused]] const ssize_t n = ::write(fd, text.data(), text.size());
            ::fsync(fd);
            ::close(fd);
        }
    } else {
        std::this_thread::sleep_for(std::chrono::seconds(3));
    }
    removeLiveTemporaries();
    ::_exit(1);
}

}  // namespace

void stopRunNow(RunOutputs& out, const std::string& paragraph, const std::string& diagnostic) {
    if (!mpi::isRoot()) stopOtherProcessNow(out, paragraph, diagnostic);
    msg().freeze();
    for (const auto& piece : emergencyEnd(paragraph, diagnostic)) msg().emergency(piece);
    if (!msg().resuText().empty() && !msg().streamError()) {
        try {
            writeResultFile(out, msg().resuText());
        } catch (const UserError& e) { reportOnStderr(e.what()); }
    }
    removeLiveTemporaries();
    if (out.messFd >= 0) ::fsync(msg().streamFd());
    ::_exit(1);
}

}  // namespace ma
