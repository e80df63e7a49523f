// The supervisor: command line, .export, the run of the command file in embedded CPython, the
// message log and result file, the timing summary, the diagnostic and the exit status.
#include "parser/Supervisor.hpp"

#include <fmt/format.h>
#include <pybind11/embed.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/AtomicFile.hpp"
#include "core/Error.hpp"
#include "core/MallocHugePages.hpp"
#include "core/Messages.hpp"
#include "core/TestReport.hpp"
#include "parser/RunState.hpp"
#include "parser/StaticCheck.hpp"
#include "xfem/SubcellQuadrature.hpp"

namespace py = pybind11;
namespace fs = std::filesystem;

namespace ma {

namespace {

const char* kUsage =
    "usage: miniaster run CASE.export [--out-dir DIR] [--check-syntax] [--subcell-quadrature RULE]\n"
    "       miniaster run CASE.comm [--mesh MESH.med] [--out-dir DIR] [--check-syntax] [--subcell-quadrature RULE]\n"
    "Runs a code_aster command file. Writes <case>.mess (message log) and <case>.resu (TEST lines,\n"
    "tables) in DIR (default: the current folder). --check-syntax validates every command call\n"
    "against the catalog without executing any. --subcell-quadrature (expert option, not a code_aster\n"
    "keyword): RULE = catalogue (default: the X-FEM sub-cell rules of code_aster's element catalogues)\n"
    "or a degree 1..6 (every volume sub-cell uses the lowest rule exact for that polynomial degree).\n"
    "Exit status: 0 OK, 2 a TEST is NOOK, 1 error.\n";

// Highest degree of --subcell-quadrature: the range XfemModel accepts.
using xfem::kMaxSubcellDegree;

struct Options {
    std::string input;
    std::string outDir = ".";
    bool outDirGiven = false;
    std::string mesh;
    bool checkOnly = false;
    int subcellDegree = 0;  // --subcell-quadrature: 0 catalogue
};

// Bad command line or .export: reported before the command file starts.
struct SetupError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw SetupError("cannot read " + path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

struct Outputs {
    std::string mess, resu;
};

// .export (commands_spec §7.8): `P name value`, `F type path flags unit`. Paths are relative to the
// .export's folder; relative result (R) paths are relative to --out-dir when it is given.
Outputs readExport(const std::string& exportPath, const Options& opt, RunState& run) {
    std::ifstream in(exportPath);
    if (!in) throw SetupError("cannot read the .export file " + exportPath);
    const fs::path folder = fs::absolute(exportPath).parent_path();
    const std::string exportName = fs::path(exportPath).filename().string();
    Outputs out;
    std::string line;
    int lineNo = 0;
    while (std::getline(in, line)) {
        ++lineNo;
        std::istringstream tokens(line);
        std::vector<std::string> t;
        for (std::string w; tokens >> w;) t.push_back(w);
        if (t.empty() || t[0][0] == '#' || t[0] != "F") continue;  // P, A, R lines: nothing to set up
        if (t.size() != 5)
            throw SetupError(fmt::format("{}, line {}: expected `F <type> <path> <D|R|...> <unit>`, got `{}`",
                                         exportName, lineNo, line));
        const std::string& type = t[1];
        const std::string& flags = t[3];
        int unit = 0;
        try {
            unit = std::stoi(t[4]);
        } catch (...) {
            throw SetupError(fmt::format("{}, line {}: the unit '{}' is not a number", exportName, lineNo, t[4]));
        }
        fs::path path = t[2];
        if (flags.find('D') != std::string::npos) {
            if (path.is_relative()) path = folder / path;
            if (!fs::exists(path))
                throw SetupError(fmt::format("{}, line {}: the data file {} of unit {} does not exist ({})", exportName,
                                             lineNo, path.string(), unit, line));
            if (type == "comm") {
                if (!run.commFile.empty())
                    throw SetupError(fmt::format("{}, line {}: several command files; miniaster runs one", exportName,
                                                 lineNo));
                run.commFile = path.string();
            } else {
                run.units.setInput(unit, path.string());
            }
        }
        if (flags.find('R') != std::string::npos) {
            if (path.is_relative()) path = (opt.outDirGiven ? fs::path(opt.outDir) : folder) / path;
            if (type == "mess") out.mess = path.string();
            else if (type == "resu") out.resu = path.string();
            else run.units.setOutput(unit, path.string());
        }
    }
    if (run.commFile.empty()) throw SetupError(exportName + ": no command file (`F comm <file> D 1`)");
    return out;
}

std::string banner() {
    return fmt::format(
        "\n {0}\n  -- CODE_ASTER -- VERSION : miniaster {1} (runs code_aster command files)\n"
        "  Embedded Python {2}\n {0}\n",
        std::string(78, '='), MINIASTER_VERSION, PY_VERSION);
}

std::string timingSummary(const RunState& run) {
    std::string out = fmt::format("\n {}\n  TIMING SUMMARY (wall time, peak resident memory of the process)\n", std::string(78, '-'));
    out += fmt::format("  {:<22} {:>6} {:>12} {:>18}\n", "command", "calls", "elapsed (s)", "peak memory (MB)");
    double total = 0;
    for (const auto& t : run.timings) {
        out += fmt::format("  {:<22} {:>6} {:>12.3f} {:>18.1f}\n", t.command, t.calls, t.seconds, t.peakKb / 1024.0);
        total += t.seconds;
    }
    out += fmt::format("  {:<22} {:>6} {:>12.3f} {:>18.1f}\n", "TOTAL (commands)", "", total, peakMemoryKb() / 1024.0);
    return out;
}

// Executes the command file; every failure ends up in run.failure.
void executeCommandFile(RunState& run) {
    const std::string source = readFile(run.commFile);
    py::module_ builtins = py::module_::import("builtins");
    py::object code;
    try {
        try {
            code = builtins.attr("compile")(py::bytes(source), run.commFile, "exec", 0, true);
        } catch (py::error_already_set& e) {
            // Files of the Python 2 era may hold latin-1 comments without a coding declaration.
            const std::string what = e.what();
            if (!e.matches(PyExc_SyntaxError) ||
                (what.find("UTF-8") == std::string::npos && what.find("utf-8") == std::string::npos))
                throw;
            py::object text = py::bytes(source).attr("decode")("latin-1");
            code = builtins.attr("compile")(text, run.commFile, "exec", 0, true);
            msg().alarm("SUPERVIS_3", "The command file is not UTF-8: it was read as latin-1.");
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
        return;
    }
    if (!checkCommandFileStatically(source, run)) return;  // every visible problem at once, nothing run
    py::dict globals;
    globals["__builtins__"] = builtins;
    globals["__name__"] = "__main__";
    globals["__file__"] = run.commFile;
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
            if (frameCode.attr("co_filename").cast<std::string>() == run.commFile)
                line = tb.attr("tb_lineno").cast<int>();
        }
        py::object value = e.value();
        const std::string type = py::str(py::type::handle_of(value).attr("__name__")).cast<std::string>();
        const std::string what = py::str(value).cast<std::string>();
        if (e.matches(PyExc_NameError) && py::hasattr(value, "name") && !value.attr("name").is_none()) {
            const std::string name = value.attr("name").cast<std::string>();
            bool upper = !name.empty();
            for (char c : name) upper = upper && (std::isupper(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c)) || c == '_');
            // A call of an unknown name in capitals: an unknown command (not an undefined variable).
            std::string lineText;
            if (line > 0) {
                std::istringstream lines(source);
                for (int k = 0; k < line && std::getline(lines, lineText); ++k) {
                }
            }
            const auto call = lineText.find(name);
            upper = upper && call != std::string::npos &&
                    lineText.find_first_not_of(" \t", call + name.size()) != std::string::npos &&
                    lineText[lineText.find_first_not_of(" \t", call + name.size())] == '(';
            if (upper) {
                run.fail("ERROR", name, line, "unknown command " + name + " (not a code_aster command known to miniaster)");
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
        if (a == "--out-dir") {
            opt.outDir = value();
            opt.outDirGiven = true;
        } else if (a == "--mesh") {
            opt.mesh = value();
        } else if (a == "--check-syntax") {
            opt.checkOnly = true;
        } else if (a == "--subcell-quadrature") {
            const std::string rule = value();
            if (rule == "catalogue") {
                opt.subcellDegree = 0;
            } else if (rule.size() == 1 && rule[0] >= '1' && rule[0] <= '0' + kMaxSubcellDegree) {
                opt.subcellDegree = rule[0] - '0';
            } else {
                throw SetupError(fmt::format("--subcell-quadrature: '{}' is not a rule (catalogue, or a polynomial "
                                             "degree 1..{})",
                                             rule, kMaxSubcellDegree));
            }
        } else if (!a.empty() && a[0] == '-') {
            throw SetupError("unknown option " + a);
        } else if (opt.input.empty()) {
            opt.input = a;
        } else {
            throw SetupError("unexpected argument " + a);
        }
    }
    if (opt.input.empty()) throw SetupError("missing CASE.export or CASE.comm");
    return opt;
}

}  // namespace

int supervisorMain(int argc, char** argv) {
    if (argc >= 2 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h")) {
        std::fputs(kUsage, stdout);
        return 0;
    }
    Options opt;
    try {
        opt = parseArguments(argc, argv);
    } catch (const SetupError& e) {
        if (*e.what()) std::fprintf(stderr, "miniaster: %s\n", e.what());
        std::fputs(kUsage, stderr);
        return 1;
    }

    RunState& run = RunState::current();
    run.checkOnly = opt.checkOnly;
    run.subcellDegree = opt.subcellDegree;
    const bool isExport = fs::path(opt.input).extension() == ".export";
    const std::string caseName = fs::path(opt.input).stem().string();
    std::error_code ec;
    fs::create_directories(opt.outDir, ec);
    run.units.setOutputDir(opt.outDir);
    Outputs outputs;
    msg().info(banner());

    try {
        if (isExport) {
            outputs = readExport(opt.input, opt, run);
        } else {
            if (!fs::exists(opt.input)) throw SetupError("the command file " + opt.input + " does not exist");
            run.commFile = opt.input;
        }
        if (!opt.mesh.empty()) {
            if (!fs::exists(opt.mesh)) throw SetupError("the mesh file " + opt.mesh + " (--mesh) does not exist");
            run.units.setInput(20, opt.mesh);
        }
    } catch (const SetupError& e) {
        run.commBaseName = fs::path(opt.input).filename().string();
        run.failure = RunFailure{"ERROR", fmt::format("<F> <ERROR> {}", e.what())};
        msg().info("\n" + run.failure->paragraph + "\n");
    }
    if (outputs.mess.empty()) outputs.mess = (fs::path(opt.outDir) / (caseName + ".mess")).string();
    if (outputs.resu.empty()) outputs.resu = (fs::path(opt.outDir) / (caseName + ".resu")).string();

    if (!run.failure) {
        run.commBaseName = fs::path(run.commFile).filename().string();
        msg().infof("  command file: {}\n  message log : {}\n  result file : {}\n  memory      : {}{}{}", run.commFile,
                    outputs.mess, outputs.resu, mallocHugePagesState(),
                    opt.checkOnly ? "\n  mode        : syntax check only (--check-syntax)" : "",
                    opt.subcellDegree ? fmt::format("\n  X-FEM       : --subcell-quadrature {} (volume sub-cells "
                                                    "integrated to degree {}, not code_aster's catalogue rules)",
                                                    opt.subcellDegree, opt.subcellDegree)
                                      : "");
        // The interpreter lives until the process ends: concepts may hold Python objects (FORMULE).
        py::initialize_interpreter();
        installCrashHandler(outputs.mess);  // after Python, which installs its own handlers
        try {
            installPythonBuiltins();
            executeCommandFile(run);
        } catch (py::error_already_set& e) {
            run.fail("ERROR", "", 0, std::string("internal error of the supervisor: ") + e.what());
        } catch (const std::exception& e) {
            run.fail("ERROR", "", 0, std::string("internal error of the supervisor: ") + e.what());
        }
        // print() output still buffered.
        try {
            py::module_::import("sys").attr("stdout").attr("flush")();
        } catch (...) {
        }
        if (!run.failure && !run.finSeen) msg().alarm("SUPERVIS_2", "The command file ended without FIN().");
    }

    // Summary, diagnostic, exit status.
    const auto& tests = testReport();
    if (!tests.empty()) msg().info("\n" + tests.summary());
    msg().info(timingSummary(run));
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

    try {
        // On an error the result file is not written: its TEST lines would be incomplete. A result
        // file of an earlier run of the same case is removed, so that it cannot be taken for this one.
        if (!run.failure && !opt.checkOnly) {
            writeFileAtomically(outputs.resu, msg().resuText());
        } else if (run.failure && fs::is_regular_file(outputs.resu)) {
            fs::remove(outputs.resu);
            msg().info("  (removed the result file of an earlier run: " + outputs.resu + ")");
        }
        writeFileAtomically(outputs.mess, msg().messText());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "miniaster: cannot write the outputs: %s\n", e.what());
        return 1;
    }
    std::fflush(stdout);
    return status;
}

}  // namespace ma
