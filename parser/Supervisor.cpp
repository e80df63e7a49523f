// The supervisor: command line, .export, the run of the command file in embedded CPython, the
// message log and result file, the timing summary, the diagnostic and the exit status.
#include "parser/Supervisor.hpp"

#include <fmt/format.h>
#include <pybind11/embed.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "core/AtomicFile.hpp"
#include "core/Error.hpp"
#include "core/MallocHugePages.hpp"
#include "core/Messages.hpp"
#include "core/Mpi.hpp"
#include "core/TestReport.hpp"
#include "parser/EmbeddedPython.hpp"
#include "parser/ExportFile.hpp"
#include "parser/ParserMessages.hpp"
#include "parser/RunGuard.hpp"
#include "parser/RunOptions.hpp"
#include "parser/RunOutputs.hpp"
#include "parser/RunState.hpp"
#include "parser/StaticCheck.hpp"

namespace py = pybind11;
namespace fs = std::filesystem;

namespace ma {

namespace {

// The usage text, with the expert run options the engine registered (parser/RunOptions.hpp).
std::string usage() {
    std::string options;
    for (const auto& [name, o] : RunOptionRegistry::instance().options())
        options += fmt::format(" [--{} {}]", name, o.valueName);
    std::string text = fmt::format(
        "usage: miniaster run CASE.export [--np K] [--out-dir DIR] [--check-syntax]{0}\n"
        "       miniaster run CASE.comm [--mesh MESH.med] [--np K] [--out-dir DIR] [--check-syntax]{0}\n"
        "Runs a code_aster command file. Writes <case>.mess (message log) and <case>.resu (TEST lines,\n"
        "tables) in DIR (default: the current folder). --check-syntax validates every command call\n"
        "against the catalog without executing any. --np K runs K MPI processes (mpirun; P mpi_nbcpu K\n"
        "in the .export does the same, the command line wins; docs/mpi.md).\n",
        options);
    for (const auto& [name, o] : RunOptionRegistry::instance().options()) text += o.help + "\n";
    return text + "Exit status: 0 OK, 2 a TEST is NOOK, 1 error.\n";
}

struct Options {
    std::string input;
    std::string outDir = ".";
    bool outDirGiven = false;
    std::string mesh;
    bool checkOnly = false;
    int processes = 0;                              // --np (0: not given)
    std::map<std::string, std::string> runOptions;  // registered expert options given
};

// Bad command line or .export: reported before the command file starts.
struct SetupError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// The command file's text; nullopt with the system's reason in `cause` when it cannot be read.
std::optional<std::string> readCommandFile(const std::string& path, std::string& cause) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        cause = systemError("cannot read the command file", path, errno);
        return std::nullopt;
    }
    std::ostringstream s;
    s << in.rdbuf();
    if (in.bad()) {
        cause = systemError("cannot read the command file", path, errno ? errno : EIO);
        return std::nullopt;
    }
    return s.str();
}

std::string banner() {
    return fmt::format(
        "\n {0}\n  -- CODE_ASTER -- VERSION : miniaster {1} (runs code_aster command files)\n"
        "  Embedded Python {2}\n {0}\n",
        std::string(78, '='), MINIASTER_VERSION, PY_VERSION);
}

std::string timingSummary(const RunState& run) {
    std::string out =
        fmt::format("\n {}\n  TIMING SUMMARY (wall time, peak resident memory of the process)\n", std::string(78, '-'));
    out += fmt::format("  {:<22} {:>6} {:>12} {:>18}\n", "command", "calls", "elapsed (s)", "peak memory (MB)");
    double total = 0;
    for (const auto& t : run.timings) {
        out += fmt::format("  {:<22} {:>6} {:>12.3f} {:>18.1f}\n", t.command, t.calls, t.seconds,
                           static_cast<double>(t.peakKb) / 1024.0);
        total += t.seconds;
    }
    out += fmt::format("  {:<22} {:>6} {:>12.3f} {:>18.1f}\n", "TOTAL (commands)", "", total,
                       static_cast<double>(peakMemoryKb()) / 1024.0);
    return out;
}

// The command file compiled (latin-1 when it is not UTF-8, alarm SUPERVIS_3); None after a
// syntax error, in run.failure.
py::object compileCommandFile(const std::string& source, const py::object& fileName, RunState& run) {
    py::module_ builtins = py::module_::import("builtins");
    py::object code;
    try {
        try {
            code = builtins.attr("compile")(py::bytes(source), fileName, "exec", 0, true);
        } catch (py::error_already_set& e) {
            // Files of the Python 2 era may hold latin-1 comments without a coding declaration.
            const std::string what = e.what();
            if (!e.matches(PyExc_SyntaxError) ||
                (what.find("UTF-8") == std::string::npos && what.find("utf-8") == std::string::npos))
                throw;
            py::object text = py::bytes(source).attr("decode")("latin-1");
            code = builtins.attr("compile")(text, fileName, "exec", 0, true);
            msg().alarm(SUPERVIS_3);
        }
    } catch (py::error_already_set& e) {
        int line = 0;
        std::string text;
        if (e.matches(PyExc_SyntaxError)) {
            py::object v = e.value();
            if (!v.attr("lineno").is_none()) line = v.attr("lineno").cast<int>();
            std::string msgText = py::str(v.attr("msg")).cast<std::string>();
            std::string offending = v.attr("text").is_none() ? "" : py::str(v.attr("text")).cast<std::string>();
            while (!offending.empty() && (offending.back() == '\n' || offending.back() == ' ')) offending.pop_back();
            text = "Python syntax error: " + msgText + (offending.empty() ? "" : ": `" + offending + "`");
        } else {
            text = std::string("cannot compile the command file: ") + e.what();
        }
        run.fail("SYNTAX_ERROR", "", line, text);
        return py::none();
    }
    return code;
}

// Executes the command file; every failure ends up in run.failure.
void executeCommandFile(RunState& run) {
    std::string cause;
    const std::optional<std::string> text = readCommandFile(run.commFile, cause);
    if (!text) {
        run.fail("ERROR", "", 0, cause);
        return;
    }
    const std::string& source = *text;
    py::module_ builtins = py::module_::import("builtins");
    // The file's name as Python sees names of the file system: any bytes, not only UTF-8.
    const py::object fileName = py::module_::import("os").attr("fsdecode")(py::bytes(run.commFile));
    const py::object code = compileCommandFile(source, fileName, run);
    if (code.is_none()) return;
    if (!checkCommandFileStatically(source, run)) return;  // every visible problem at once, nothing run
    py::dict globals;
    globals["__builtins__"] = builtins;
    globals["__name__"] = "__main__";
    globals["__file__"] = fileName;
    py::module_ miniaster = py::module_::import("_miniaster");
    try {
        builtins.attr("exec")(code, globals);
    } catch (py::error_already_set& e) {
        if (e.matches(miniaster.attr("EndOfRun"))) return;  // FIN()
        if (e.matches(miniaster.attr("Abort")) || run.failure) return;
        // An exception in the Python code of the command file: the innermost line of the file.
        int line = 0;
        for (py::handle tb = e.trace(); tb && !tb.is_none(); tb = tb.attr("tb_next")) {
            py::object frameCode = tb.attr("tb_frame").attr("f_code");
            if (py::object(frameCode.attr("co_filename")).equal(fileName)) line = tb.attr("tb_lineno").cast<int>();
        }
        py::object value = e.value();
        const std::string type = py::str(py::type::handle_of(value).attr("__name__")).cast<std::string>();
        const std::string what = py::str(value).cast<std::string>();
        if (e.matches(PyExc_NameError) && py::hasattr(value, "name") && !value.attr("name").is_none()) {
            const std::string name = value.attr("name").cast<std::string>();
            bool upper = !name.empty();
            for (char c : name)
                upper = upper && (std::isupper(static_cast<unsigned char>(c)) ||
                                  std::isdigit(static_cast<unsigned char>(c)) || c == '_');
            // A call of an unknown name in capitals: an unknown command (not an undefined variable).
            std::string lineText;
            if (line > 0) {
                std::istringstream lines(source);
                for (int k = 0; k < line && std::getline(lines, lineText); ++k) {}
            }
            const auto call = lineText.find(name);
            upper = upper && call != std::string::npos &&
                    lineText.find_first_not_of(" \t", call + name.size()) != std::string::npos &&
                    lineText[lineText.find_first_not_of(" \t", call + name.size())] == '(';
            if (upper) {
                run.fail("ERROR", name, line,
                         "unknown command " + name + " (not a code_aster command known to miniaster)");
                return;
            }
        }
        run.fail("ERROR", "", line, fmt::format("error in the Python code of the command file: {}: {}", type, what));
    }
}

Options parseArguments(int argc, char** argv) {
    Options opt;
    if (argc < 3 || std::string(argv[1]) != "run") throw SetupError("");
    for (int i = 2; i < argc; ++i) {
        std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) throw SetupError(a + " needs a value");
            return argv[++i];
        };
        auto path = [&]() -> std::string {
            std::string v = value();
            if (v.empty()) throw SetupError(a + " needs a value, got an empty one");
            return v;
        };
        if (a == "--out-dir") {
            opt.outDir = path();
            opt.outDirGiven = true;
        } else if (a == "--mesh") {
            opt.mesh = path();
        } else if (a == "--np") {
            const std::string v = value();
            const bool number = !v.empty() && v.find_first_not_of("0123456789") == std::string::npos && v.size() < 6;
            opt.processes = number ? std::stoi(v) : 0;
            if (opt.processes < 1 || opt.processes > kMaxProcesses)
                throw SetupError(
                    fmt::format("--np needs a number of processes from 1 to {}, got '{}'", kMaxProcesses, v));
            if (opt.processes != mpi::size())
                throw SetupError(fmt::format("--np {}: this run has {} MPI process(es) (mpirun -np {})", opt.processes,
                                             mpi::size(), mpi::size()));
        } else if (a == "--check-syntax") {
            opt.checkOnly = true;
        } else if (const RunOption* o =
                       a.starts_with("--") ? RunOptionRegistry::instance().find(a.substr(2)) : nullptr) {
            const std::string v = value();
            if (const std::string why = o->check(v); !why.empty()) throw SetupError(a + ": " + why);
            opt.runOptions[o->name] = v;
        } else if (!a.empty() && a[0] == '-') {
            throw SetupError("unknown option " + a);
        } else if (a.empty()) {
            throw SetupError("an empty argument: the case (.export or .comm) has no name");
        } else if (opt.input.empty()) {
            opt.input = a;
        } else {
            throw SetupError("unexpected argument " + a);
        }
    }
    if (opt.input.empty()) throw SetupError("missing CASE.export or CASE.comm");
    return opt;
}

// Where the watchdog's stop ends the run (parser/RunGuard.hpp).
RunOutputs* gOutputs = nullptr;

void stopFromWatchdog(const std::string& kind, const std::string& cause) {
    const auto& run = RunState::current();
    const std::string where =
        run.runningCommand[0] ? fmt::format("{} ({}, line {})", run.runningCommand, run.commBaseName, run.runningLine)
        : run.runningLine
            ? fmt::format("({}, in the Python code after the command of line {})", run.commBaseName, run.runningLine)
            : fmt::format("({})", run.commBaseName);
    stopRunNow(*gOutputs, fmt::format("<F> <{}> {}: {}", kind, where, cause), "<F>_" + kind);
}

// The .export or the command line, resolved into units and output paths (absolute: the command
// file may change the current folder). SetupError / UserError / ExportError on a bad input.
RunLimits setUpRun(const Options& opt, RunState& run, RunOutputs& outputs) {
    RunLimits limits;
    if (fs::path(opt.input).extension() == ".export") {
        const ExportFile exportFile =
            readExportFile(opt.input, opt.outDirGiven ? std::optional<fs::path>(outputs.outDir) : std::nullopt);
        applyExport(exportFile, run, outputs);
        limits.timeLimitSeconds = exportFile.timeLimitSeconds;
        limits.memoryLimitMb = exportFile.memoryLimitMb;
    } else {
        std::error_code ec;
        if (!fs::exists(opt.input, ec)) throw SetupError("the command file " + opt.input + " does not exist");
        if (fs::is_directory(opt.input, ec)) throw SetupError("the command file " + opt.input + " is a folder");
        if (!fs::is_regular_file(opt.input, ec))
            throw SetupError("the command file " + opt.input + " is not a regular file (" + kNotRegular + ")");
        run.commFile = fs::absolute(opt.input).lexically_normal().string();
    }
    if (!opt.mesh.empty()) {
        std::error_code ec;
        if (!fs::exists(opt.mesh, ec)) throw SetupError("the mesh file " + opt.mesh + " (--mesh) does not exist");
        if (!fs::is_regular_file(opt.mesh, ec))
            throw SetupError("the mesh file " + opt.mesh + " (--mesh) is not a regular file (" + kNotRegular + ")");
        run.units.setInput(20, fs::absolute(opt.mesh).lexically_normal().string());
    }
    run.units.setOutputDir(outputs.resultFolders.empty() ? outputs.outDir : outputs.resultFolders.front());
    return limits;
}

// The outputs checked and the .mess opened by rank 0 (the other processes write nothing); every
// process learns whether that worked. An exit status when the run cannot start.
std::optional<int> openOutputs(RunOutputs& outputs, const RunState& run, const std::string& exportFile,
                               const std::optional<std::string>& setupFailure) {
    std::optional<mpi::Failure> failure;
    if (mpi::isRoot()) {
        try {
            prepareOutputs(outputs, run, exportFile);
            openMessageLog(outputs);
        } catch (const UserError& e) { failure = mpi::Failure{0, e.what()}; }
    }
    failure = mpi::agree(failure);
    if (!failure) return std::nullopt;
    if (mpi::isRoot()) {
        if (setupFailure) std::fprintf(stderr, "miniaster: %s\n", setupFailure->c_str());
        std::fprintf(stderr, "miniaster: %s; nothing was run\n", failure->text.c_str());
    }
    return 1;
}

// The header of the .mess, then the command file in the embedded interpreter.
void runCommandFile(const Options& opt, RunState& run, RunOutputs& outputs, const RunLimits& limits) {
    run.commBaseName = fs::path(run.commFile).filename().string();
    std::string announced;
    for (const auto& [name, value] : opt.runOptions)
        if (const std::string line = RunOptionRegistry::instance().find(name)->announce(value); !line.empty())
            announced += "\n  " + line;
    if (limits.timeLimitSeconds || limits.memoryLimitMb)
        announced +=
            fmt::format("\n  limits      : {}{}",
                        limits.timeLimitSeconds ? fmt::format("time {:g} s (CPU) ", *limits.timeLimitSeconds) : "",
                        limits.memoryLimitMb ? fmt::format("memory {:g} MB (resident)", *limits.memoryLimitMb) : "");
    if (const std::string note = pythonHomeNote(); !note.empty()) announced += "\n  " + note;
    msg().infof(
        "  command file: {}\n  message log : {}\n  result file : {}\n  memory      : {}\n  MPI processes: {}{}{}",
        run.commFile, outputs.mess, outputs.resu, mallocPagesState(), mpi::size(),
        opt.checkOnly ? "\n  mode        : syntax check only (--check-syntax)" : "", announced);
    // The interpreter lives until the process ends: concepts may hold Python objects (FORMULE).
    if (const auto refused = startEmbeddedPython()) {
        run.fail("ERROR", "", 0, *refused);
        return;
    }
    installCrashHandler(outputs.messFd);  // after Python, which installs its own handlers
    startRunGuard(limits, stopFromWatchdog);
    try {
        installPythonBuiltins();
        executeCommandFile(run);
        if (isForkedChild()) ::_exit(0);  // forked without Python's hooks: the parent ends the run
    } catch (py::error_already_set& e) {
        run.fail("ERROR", "", 0, std::string("internal error of the supervisor: ") + e.what());
    } catch (const std::exception& e) { run.fail("ERROR", "", 0, unexpectedErrorCause(e)); }
    agreeWithOtherProcesses(run);  // the last command's agreement met this one's or a failure's
    // print() output still buffered.
    try {
        py::module_::import("sys").attr("stdout").attr("flush")();
    } catch (...) {}
    if (!run.failure && !run.finSeen) msg().alarm(SUPERVIS_2);
}

// Summary, diagnostic, the outputs closed (rank 0); the exit status.
int finishRun(const Options& opt, const RunState& run, RunOutputs& outputs) {
    const auto& tests = testReport();
    if (!tests.empty()) msg().info("\n" + tests.summary());
    msg().info(timingSummary(run));
    for (const auto& [id, count] : msg().ignoredAlarms())
        msg().infof("\n <I> alarm {} raised {} time(s), not printed (DEBUT/IGNORE_ALARM)", id, count);
    if (run.finSeen && !run.failure) msg().info("\n <I> <FIN> ARRET NORMAL DANS \"FIN\" PAR APPEL A \"JEFINI\".");

    std::string diagnostic;
    int status = 0;
    if (run.failure) {
        diagnostic = "<F>_" + run.failure->kind;
        status = 1;
    } else if (opt.checkOnly) {
        diagnostic = "SYNTAX_OK (no command executed)";
    } else if (tests.nookCount() > 0) {
        diagnostic = "NOOK_TEST_RESU";
        status = 2;
    } else if (msg().alarmCount() > 0) {
        diagnostic = "<A>_ALARM";
    } else {
        diagnostic = "OK";
    }
    const std::string rule(60, '-');
    msg().info(fmt::format("\n{}\n--- DIAGNOSTIC JOB : {}\n{}", rule, diagnostic, rule));

    if (mpi::isRoot() && !finishOutputs(outputs, run.failure.has_value(), opt.checkOnly)) status = 1;
    installCrashHandler(-1);  // the .mess is closed
    std::fflush(stdout);
    return status;
}

}  // namespace

// Every process runs the same command file (docs/mpi.md); only rank 0 prints and writes.
int supervisorMain(int argc, char** argv) {
    if (argc >= 2 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h")) {
        if (mpi::isRoot()) std::fputs(usage().c_str(), stdout);
        return 0;
    }
    if (!mpi::isRoot()) msg().setEcho(false);
    Options opt;
    try {
        opt = parseArguments(argc, argv);
    } catch (const SetupError& e) {
        if (mpi::isRoot() && *e.what()) std::fprintf(stderr, "miniaster: %s\n", e.what());
        if (mpi::isRoot()) std::fputs(usage().c_str(), stderr);
        return 1;
    }

    RunState& run = RunState::current();
    run.checkOnly = opt.checkOnly;
    run.runOptions = opt.runOptions;
    const std::string caseName = fs::path(opt.input).stem().string();
    RunOutputs outputs;
    gOutputs = &outputs;
    outputs.outDir = fs::absolute(opt.outDir).lexically_normal().string();
    msg().info(banner());

    // Setup, before the first command: a bad .export or input is logged in the .mess (when the
    // output folder can hold one); an output that cannot be written stops the run at once.
    RunLimits limits;
    std::optional<std::string> setupFailure;
    try {
        limits = setUpRun(opt, run, outputs);
    } catch (const std::exception& e) {  // SetupError, ExportError, UserError
        setupFailure = e.what();
    }
    if (outputs.mess.empty()) outputs.mess = (fs::path(outputs.outDir) / (caseName + ".mess")).string();
    if (outputs.resu.empty()) outputs.resu = (fs::path(outputs.outDir) / (caseName + ".resu")).string();
    const std::string exportFile = fs::path(opt.input).extension() == ".export" ? opt.input : "";
    if (const auto status = openOutputs(outputs, run, exportFile, setupFailure)) return *status;
    if (setupFailure) {
        run.commBaseName = fs::path(opt.input).filename().string();
        run.failure = RunFailure{"ERROR", fmt::format("<F> <ERROR> {}", *setupFailure)};
        msg().info("\n" + run.failure->paragraph + "\n");
    }
    if (!run.failure) runCommandFile(opt, run, outputs, limits);
    stopRunGuard();
    return finishRun(opt, run, outputs);
}

}  // namespace ma
