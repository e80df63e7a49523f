// The Python side of the supervisor: the `_miniaster` embedded module, the builtins of a command
// file (every catalogued command, _F), the opaque concept objects handed to Python, and the call
// of one command: Python arguments -> catalog validation -> KeywordSet -> registered C++ command.
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <pybind11/embed.h>
#include <pybind11/stl.h>
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <malloc.h>
#include <set>
#include <sstream>
#include <unistd.h>

#include "core/Error.hpp"
#include "core/MemoryLimit.hpp"
#include "core/MemoryUsage.hpp"
#include "core/Messages.hpp"
#include "core/Mpi.hpp"
#include "parser/Catalog.hpp"
#include "parser/CommandRegistry.hpp"
#include "parser/Formula.hpp"
#include "parser/ParserMessages.hpp"
#include "parser/PythonValues.hpp"
#include "parser/RunGuard.hpp"
#include "parser/RunState.hpp"
#include "parser/RunSummary.hpp"

namespace py = pybind11;

namespace ma {

namespace {

// Raised (as Python BaseException subclasses, so that `except Exception` in user code does not
// swallow them) to unwind the command file: after a recorded failure, and by FIN().
struct AbortRun {
    const char* what() const noexcept { return "the run is stopped by an error"; }
};
struct EndOfRun {
    const char* what() const noexcept { return "FIN"; }
};

// Result of --check-syntax for an operator: a typed stand-in so that later calls can be checked.
class SyntaxPlaceholder : public Concept {
public:
    explicit SyntaxPlaceholder(std::string type) : type_(std::move(type)) {}
    std::string typeName() const override { return type_; }

private:
    std::string type_;
};

bool isInput(const CallValue& v, const ConceptPtr& c) {
    if (v.kind == CallValue::Kind::Concept) return v.object == c;
    for (const auto& item : v.items)
        if (isInput(item, c)) return true;
    for (const auto& [k, item] : v.dict)
        if (isInput(item, c)) return true;
    return false;
}
bool isInput(const CallArguments& args, const ConceptPtr& c) {
    for (const auto& [k, v] : args)
        if (isInput(v, c)) return true;
    return false;
}

py::object wrap(const ConceptPtr& c) {
    if (!c) return py::none();
    return py::cast(ConceptHandle{c});
}

// ------------------------------------------------------------------------------------------
// Python bootstrap: builtins, result naming from the caller's bytecode, output redirection.

const char* kBootstrap = R"PY(
import builtins, dis, sys
import _miniaster

def _F(**keywords):
    """Factor keyword occurrence: a plain dict, as in code_aster."""
    return dict(keywords)

def _make_command(name):
    def command(*args, **keywords):
        return _miniaster.command(name, sys._getframe(1), args, keywords)
    command.__name__ = command.__qualname__ = name
    return command

for _name in _miniaster.command_names():
    setattr(builtins, _name, _make_command(_name))
builtins._F = _F

# The math names code_aster puts in every command file's namespace (code_aster/Cata/context.py):
# sslv318a computes its reference with sqrt.
import math as _math
for _name in ("acos", "asin", "atan", "atan2", "cos", "cosh", "exp", "log", "log10", "pi", "sin", "sinh",
              "sqrt", "tan", "tanh"):
    setattr(builtins, _name, getattr(_math, _name))

# Files written for code_aster ≥ 14 may start with `from code_aster.Commands import *`.
import types as _types
_code_aster = _types.ModuleType("code_aster")
_code_aster.Commands = _types.ModuleType("code_aster.Commands")
for _name in _miniaster.command_names():
    setattr(_code_aster.Commands, _name, getattr(builtins, _name))
_code_aster.Commands._F = _F
_code_aster.Commands.__all__ = list(_miniaster.command_names()) + ["_F"]
sys.modules["code_aster"] = _code_aster
sys.modules["code_aster.Commands"] = _code_aster.Commands

_STORE = {"STORE_NAME", "STORE_GLOBAL", "STORE_FAST", "STORE_DEREF"}
_LOAD = {"LOAD_NAME", "LOAD_GLOBAL", "LOAD_FAST", "LOAD_DEREF"}
_instructions = {}

def result_name(frame):
    """Name of the variable the pending call's result is stored in: `A = CMD()` -> 'A',
    `T[i] = CMD()` -> 'T_<value of i>' (legacy code_aster rule), else ''."""
    code = frame.f_code
    instrs = _instructions.get(code)
    if instrs is None:
        instrs = _instructions[code] = [i for i in dis.get_instructions(code) if i.opname != "CACHE"]
    # f_lasti is the CALL (or, in 3.11, one of its inline cache entries): what follows it.
    index = next((k for k, i in enumerate(instrs) if i.offset > frame.f_lasti), None)
    if index is None:
        return ""
    following = instrs[index:index + 3]
    if following and following[0].opname in _STORE:
        return str(following[0].argval)
    if (len(following) == 3 and following[0].opname in _LOAD and following[2].opname == "STORE_SUBSCR"):
        key = following[1]
        if key.opname == "LOAD_CONST":
            value = key.argval
        elif key.opname in _LOAD:
            name = key.argval
            value = frame.f_locals.get(name, frame.f_globals.get(name, builtins.__dict__.get(name, "")))
        else:
            return ""
        return "%s_%s" % (following[0].argval, value)
    return ""

def function_echo(f):
    """A Python function given to FORMULE, for the echo: its source (file, line) and the values
    of the plain names it reads from the file or its closure (numbers, strings...)."""
    import inspect, os
    code = f.__code__
    try:
        lines, first = inspect.getsourcelines(f)
    except (OSError, TypeError):
        lines, first = [], code.co_firstlineno
    out = ["# %s (%s, line %d)" % (f.__name__, os.path.basename(code.co_filename), first)]
    out += ["#   " + l.rstrip() for l in lines[:20]] + (["#   ... (%d more lines)" % (len(lines) - 20)] if len(lines) > 20 else [])
    values = {n: c.cell_contents for n, c in zip(code.co_freevars, f.__closure__ or ()) if c.cell_contents is not None}
    names = set(code.co_names).union(*(c.co_names for c in code.co_consts if hasattr(c, "co_names")))
    values.update({n: f.__globals__[n] for n in sorted(names) if n in f.__globals__ and n not in values})
    shown = ["%s=%r" % (k, v) for k, v in values.items() if isinstance(v, (int, float, complex, str, bool))]
    return "\n".join(out + (["#   with " + ", ".join(shown)] if shown else []))

class _LogWriter:
    """print() in the command file goes to the message log."""
    def __init__(self):
        self._pending = ""
    def write(self, text):
        self._pending += text
        while "\n" in self._pending:
            line, self._pending = self._pending.split("\n", 1)
            _miniaster.log(line)
        return len(text)
    def flush(self):
        if self._pending:
            _miniaster.log(self._pending)
            self._pending = ""
    def isatty(self):
        return False

# A child forked by the command file (os.fork, multiprocessing) ends at once, quietly: it must not
# run the rest of the file nor write the run's outputs (parser/RunGuard.hpp).
def _forked():
    line = sys._getframe(1).f_lineno  # the caller of os.fork (the hooks run from C)
    _miniaster.log(" <I> os.fork() (line %d): the child process ended at once without running the rest of the "
                   "command file (a run is one process per MPI rank)" % line)
import os as _os
_os.register_at_fork(after_in_child=_miniaster.end_forked_child, after_in_parent=_forked)

sys.stdout = _LogWriter()
sys.stderr = _LogWriter()
)PY";

// MINIASTER_UNREGISTER=NAME1,NAME2: behave as if these commands had no implementation (lets the
// tests check the "not implemented yet" path whatever the state of the other commands).
bool isDisabledForTests(const std::string& name) {
    const char* list = std::getenv("MINIASTER_UNREGISTER");
    if (!list) return false;
    const std::string s = std::string(",") + list + ",";
    return s.find("," + name + ",") != std::string::npos;
}

py::object& resultNameFunction() {
    static auto* f = new py::object();  // leaked: released after the interpreter otherwise
    return *f;
}

py::object& functionEchoFunction() {
    static auto* f = new py::object();  // leaked, as above
    return *f;
}

// ------------------------------------------------------------------------------------------
// One command call

std::string echoCall(const std::string& resultName, const std::string& command, const KeywordSet& kw,
                     const std::string& extra) {
    std::string body = kw.echo(4) + extra;
    std::string head = (resultName.empty() ? "" : resultName + " = ") + command + "(";
    if (body.empty()) return head + ")";
    return head + "\n" + body + ")";
}

int currentLine() {
    try {
        return py::module_::import("sys").attr("_getframe")(0).attr("f_lineno").cast<int>();
    } catch (...) { return 0; }
}

// FORMULE: validated VALE / NOM_PARA, other keywords are the evaluation context.
ConceptPtr makeFormula(const KeywordSet& kw, const py::dict& context, const py::dict& globals, int line) {
    const auto& run = RunState::current();
    return std::make_shared<Formula>(kw.text("VALE"), kw.texts("NOM_PARA"), context, globals, run.commFile, line);
}

// reuse= (reentrant commands only): the object it names, taken out of the keywords; null without.
ConceptPtr takeReused(const cata::Command& command, py::dict keywords, const std::string& resultName) {
    const std::string& name = command.name;
    ConceptPtr reused;
    if (keywords.contains("reuse")) {
        py::object r = keywords["reuse"];
        PyDict_DelItemString(keywords.ptr(), "reuse");
        if (command.reentrant == cata::Reuse::No)
            throw UserError(fmt::format("reuse= is not allowed: {} is not a reentrant command", name));
        if (!py::isinstance<ConceptHandle>(r))
            throw UserError(fmt::format("reuse= expects a concept, got {}", toCallValue(r).describe()));
        reused = r.cast<ConceptHandle&>().object;
        if (!resultName.empty() && !reused->name.empty() && reused->name != resultName)
            throw UserError(
                fmt::format("reuse={} but the result is assigned to {}: a reentrant command "
                            "modifies the object given by reuse=, assign the result to it",
                            reused->name, resultName));
    }
    if (!reused && command.reentrant == cata::Reuse::Mandatory)
        throw UserError(
            fmt::format("{0} modifies its input in place: reuse= is mandatory (write X = {0}(reuse=X, "
                        "...) with the object it modifies)",
                        name));
    return reused;
}

// The echo of the call in code_aster's style (and the alarm of a file that does not start with DEBUT).
void echoCommand(const CommandContext& ctx, const KeywordSet& kw, const py::dict& context,
                 const std::string& resultType) {
    auto& run = RunState::current();
    const std::string& name = ctx.command;
    ++run.commandCount;
    std::string extra;
    for (auto [k, v] : context) {
        // Functions by name (their repr holds an address, which would make logs differ run to run).
        const std::string shown = py::hasattr(v, "__name__") && !py::isinstance<ConceptHandle>(v)
                                      ? v.attr("__name__").cast<std::string>()
                                      : py::repr(v).cast<std::string>();
        extra += fmt::format("    {}={},\n", py::str(k).cast<std::string>(), shown);
        // A function's values are inside it: its source and the values it reads go with it.
        if (py::hasattr(v, "__code__")) {
            std::string text;
            try {
                text = functionEchoFunction()(v).cast<std::string>();
            } catch (py::error_already_set&) {}  // an echo only: the formula itself is checked when used
            std::istringstream source(text);
            for (std::string l; std::getline(source, l);) extra += "        " + l + "\n";
        }
    }
    msg().info(fmt::format("\n # {}\n # Command #{:04d} from {}, line {}{}\n{}\n", std::string(78, '-'),
                           run.commandCount, run.commBaseName, ctx.line,
                           resultType.empty() ? "" : ", result of type " + resultType,
                           echoCall(ctx.resultName, name, kw, extra)));
    if (!run.debutSeen && name != "DEBUT" && !run.missingDebutReported) {
        run.missingDebutReported = true;
        msg().alarm(SUPERVIS_1);
    }
}

// DETRUIRE: the names the command file gave these concepts leave its namespace (a later use is a
// NameError, the name can be given again); the memory goes with the last reference, so a mesh a
// result still uses stays until that result goes too.
void destroyConcepts(const KeywordSet& kw, const py::object& frame) {
    std::set<const Concept*> targets;
    for (const auto& occ : kw.factor("CONCEPT"))
        for (const auto& c : occ.objects<Concept>("NOM")) targets.insert(c.get());
    py::dict globals = frame.attr("f_globals");
    std::vector<std::string> names;
    for (const auto& [key, value] : globals)
        if (py::isinstance<ConceptHandle>(value) && targets.count(value.cast<ConceptHandle&>().object.get()))
            names.push_back(key.cast<std::string>());
    for (const auto& n : names) globals.attr("pop")(n);
    msg().infof("    {} removed from the command file's names",
                names.empty() ? "nothing" : fmt::format("{}", fmt::join(names, ", ")));
}

// Runs the validated call: DEBUT, FIN, FORMULE and PRE_GIBI here, the others through the registry
// (or not at all with --check-syntax). Checks the result's type against the catalog.
ConceptPtr execute(CommandContext& ctx, const KeywordSet& kw, const py::dict& context, py::object frame,
                   const std::string& resultType) {
    auto& run = RunState::current();
    const std::string& name = ctx.command;
    ConceptPtr result;
    if (name == "DEBUT") {
        if (run.debutSeen) throw UserError("DEBUT is called twice");
        run.debutSeen = true;
        if (kw.has("IGNORE_ALARM")) {
            msg().ignoreAlarms(kw.texts("IGNORE_ALARM"));
            msg().infof("    alarms {} are not printed (DEBUT/IGNORE_ALARM); their count is given at the end",
                        fmt::join(kw.texts("IGNORE_ALARM"), ", "));
        }
    } else if (name == "FIN") {
        run.finSeen = true;
        run.recordTiming(name, 0.0);
        throw EndOfRun{};
    } else if (name == "FORMULE") {
        result = makeFormula(kw, context, frame.attr("f_globals").cast<py::dict>(), ctx.line);
    } else if (name == "DETRUIRE") {
        if (!run.checkOnly) destroyConcepts(kw, frame);
    } else if (name == "PRE_GIBI") {
        msg().info("    PRE_GIBI is a no-op in miniaster: LIRE_MAILLAGE reads the MED mesh of unit " +
                   std::to_string(kw.integer("UNITE_MAILLAGE")) + " instead of a converted GIBI mesh");
    } else if (run.checkOnly) {
        if (!resultType.empty()) result = std::make_shared<SyntaxPlaceholder>(resultType);
        msg().info("    syntax checked; not executed (--check-syntax)");
    } else {
        const CommandFunction* fn = CommandRegistry::instance().find(name);
        if (isDisabledForTests(name)) fn = nullptr;
        if (!fn) throw NotImplemented(name + " is not implemented yet in miniaster");
        {
            // Commands run without the GIL: they may use threads; formulas re-acquire it.
            py::gil_scoped_release noGil;
            result = (*fn)(kw, ctx);
        }
        if (!result && !resultType.empty()) throw InternalError(fmt::format("{} returned no {}", name, resultType));
        if (result && !resultType.empty() && result->typeName() != resultType)
            throw InternalError(fmt::format("{} returned a concept of type {}, the catalog says {}", name,
                                            result->typeName(), resultType));
    }
    return result;
}

// Python keyword arguments -> call arguments; FORMULE's keywords other than VALE, VALE_C and
// NOM_PARA go to `context` (its evaluation context) as Python objects.
CallArguments callArguments(const std::string& name, const py::dict& keywords, py::dict& context) {
    CallArguments callArgs;
    for (auto [k, v] : keywords) {
        const std::string key = py::str(k).cast<std::string>();
        if (name == "FORMULE" && key != "VALE" && key != "VALE_C" && key != "NOM_PARA") {
            context[k] = v;
            continue;
        }
        callArgs.emplace_back(key, toCallValue(v, key));
    }
    return callArgs;
}

py::object runCommand(const std::string& name, py::object frame, py::tuple args, py::dict keywords) {
    if (isForkedChild()) ::_exit(0);  // forked without Python's hooks (ctypes): quietly, before any output
    auto& run = RunState::current();
    if (!run.failure) agreeWithOtherProcesses(run);  // a process may have failed in the Python code
    if (run.failure) throw AbortRun{};
    const int line = frame.attr("f_lineno").cast<int>();
    const auto started = std::chrono::steady_clock::now();
    std::string resultName;
    try {
        resultName = resultNameFunction()(frame).cast<std::string>();
        if (std::find(unsupportedCommands().begin(), unsupportedCommands().end(), name) != unsupportedCommands().end())
            throw NotImplemented("command " + name + " is not supported by miniaster");
        const cata::Command* command = Catalog::instance().find(name);
        if (!command) throw UserError("unknown command " + name);
        if (!args.empty())
            throw UserError(fmt::format("{} takes keyword arguments only (got {} positional argument{})", name,
                                        args.size(), args.size() > 1 ? "s" : ""));

        const ConceptPtr reused = takeReused(*command, keywords, resultName);

        // Python arguments -> checked keyword tree. FORMULE keeps its extra keywords as Python objects.
        py::dict context;
        const CallArguments callArgs = callArguments(name, keywords, context);
        KeywordSet kw = validateCall(*command, callArgs);

        CommandContext ctx;
        ctx.command = name;
        ctx.resultName = resultName;
        ctx.reused = reused;
        ctx.commFile = run.commFile;
        ctx.line = line;
        ctx.units = &run.units;
        ctx.runOptions = run.runOptions;
        if (kw.simpleKeywords().count("INFO")) ctx.info = static_cast<int>(kw.integer("INFO"));

        const std::string resultType = command->resultType(kw);
        echoCommand(ctx, kw, context, resultType);

        std::snprintf(run.runningCommand, sizeof(run.runningCommand), "%s", name.c_str());
        run.runningLine = line;
        const ConceptPtr result = execute(ctx, kw, context, frame, resultType);
        // The result takes the variable's name, unless it is one of the call's input objects returned
        // as is (it keeps its name; with reuse= the names are the same).
        if (result && !resultName.empty() && (result == reused || !isInput(callArgs, result)))
            result->name = resultName;

        // What the command freed goes back to the system: glibc keeps freed heap pages resident,
        // and P memory_limit watches resident memory (ssnp138a's five solves in one run).
        malloc_trim(0);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
        run.runningCommand[0] = '\0';
        run.recordTiming(name, seconds);
        if (run.consoleSummary) printCommandEnd(name, line, seconds);
        msg().info(fmt::format(" # end of {} (line {}): elapsed {:.3f} s, peak memory {:.1f} MB", name, line, seconds,
                               static_cast<double>(peakMemoryKb()) / 1024.0));
        agreeWithOtherProcesses(run);
        if (run.failure) throw AbortRun{};
        return wrap(result);
    } catch (const AbortRun&) { throw; } catch (const EndOfRun&) {
        throw;
    } catch (const mpi::OtherProcessFailed&) {  // the failure is learned in the agreement below
    } catch (py::error_already_set& e) {
        if (run.failure) throw AbortRun{};
        run.fail("ERROR", name, line, fmt::format("Python error: {}", e.what()));
    } catch (const UserError& e) { run.fail("ERROR", name, line, e.what()); } catch (const NotImplemented& e) {
        run.fail("ERROR", name, line, e.what());
    } catch (const NumericalError& e) {
        run.fail("ERROR", name, line, std::string("numerical failure: ") + e.what());
    } catch (const InternalError& e) {
        run.fail("ERROR", name, line, std::string("internal error of miniaster (please report it): ") + e.what());
    } catch (const std::bad_alloc&) {
        run.fail("ERROR", name, line, outOfMemoryCause());
    } catch (const std::exception& e) { run.fail("ERROR", name, line, unexpectedErrorCause(e)); } catch (...) {
        run.fail("ERROR", name, line, "unexpected error of unknown type");
    }
    agreeWithOtherProcesses(run);
    throw AbortRun{};
}

// Calling a function concept from Python: F(1.0, 2.0).
py::object callConcept(ConceptHandle& self, py::args args) {
    auto& run = RunState::current();
    auto f = std::dynamic_pointer_cast<Function>(self.object);
    if (!f) throw py::type_error(fmt::format("{} ({}) is not a function", self.object->name, self.object->typeName()));
    if (args.size() != f->parameters().size() && !f->parameters().empty())  // DEFI_CONSTANTE takes any
        throw py::type_error(fmt::format("{}() takes {} argument(s) ({}), got {}", self.object->name,
                                         f->parameters().size(), fmt::join(f->parameters(), ", "), args.size()));
    std::vector<double> values;
    for (auto a : args) {
        try {
            values.push_back(a.cast<double>());
        } catch (const py::cast_error&) {
            throw py::type_error(
                fmt::format("{}(): arguments must be numbers, got {}", self.object->name, toCallValue(a).describe()));
        }
    }
    try {
        return py::float_(f->evaluate(values));
    } catch (py::error_already_set&) {
        if (run.failure) throw AbortRun{};
        throw;
    } catch (const UserError& e) {
        run.fail("ERROR", self.object->name, currentLine(), e.what());
    } catch (const NumericalError& e) { run.fail("ERROR", self.object->name, currentLine(), e.what()); }
    throw AbortRun{};
}

}  // namespace

void agreeWithOtherProcesses(RunState& run) {
    if (mpi::size() == 1) return;
    std::optional<mpi::Failure> local;
    if (run.failure) local = mpi::Failure{0, run.failure->paragraph};
    const auto agreed = mpi::agreeOnRun(local);
    if (!agreed || run.failure) return;
    const std::string paragraph =
        fmt::format("{}\n  (on MPI process {} of {})", agreed->text, agreed->rank, mpi::size());
    run.failure = RunFailure{"ERROR", paragraph};
    msg().info("\n" + paragraph + "\n");
}

PYBIND11_EMBEDDED_MODULE(_miniaster, m) {
    py::register_exception<AbortRun>(m, "Abort", PyExc_BaseException);
    py::register_exception<EndOfRun>(m, "EndOfRun", PyExc_BaseException);

    py::class_<ConceptHandle>(m, "Concept")
        .def("__call__", &callConcept)
        .def("__repr__",
             [](const ConceptHandle& h) {
                 return fmt::format("<{} {}>", h.object->typeName(), h.object->name.empty() ? "?" : h.object->name);
             })
        .def_property_readonly("nom", [](const ConceptHandle& h) { return h.object->name; })
        .def("getName", [](const ConceptHandle& h) { return h.object->name; })
        .def("getType", [](const ConceptHandle& h) { return h.object->typeName(); })
        .def("__eq__",
             [](const ConceptHandle& a, py::object b) {
                 return py::isinstance<ConceptHandle>(b) && b.cast<ConceptHandle&>().object == a.object;
             })
        .def("__hash__", [](const ConceptHandle& h) { return std::hash<const void*>()(h.object.get()); });

    m.def("command", &runCommand);
    m.def("command_names", [] {
        std::vector<std::string> names;
        for (const auto& [n, c] : Catalog::instance().commands()) names.push_back(n);
        for (const auto& n : unsupportedCommands()) names.push_back(n);
        return names;
    });
    m.def("log", [](const std::string& line) { msg().info(line); });
    m.def("end_forked_child", [] { ::_exit(0); });
}

void installPythonBuiltins() {
    py::dict ns;
    ns["__builtins__"] = py::module_::import("builtins");
    py::exec(kBootstrap, ns);
    resultNameFunction() = ns["result_name"];
    functionEchoFunction() = ns["function_echo"];
}

// ------------------------------------------------------------------------------------------
// Run state

RunState& RunState::current() {
    static RunState state;
    return state;
}

void RunState::fail(const std::string& kind, const std::string& who, int line, const std::string& cause) {
    if (failure) return;
    std::string where = line > 0 ? fmt::format("({}, line {})", commBaseName, line) : fmt::format("({})", commBaseName);
    // Causes quote inputs (a value, a Python exception's text): a bounded paragraph.
    std::string paragraph = fmt::format("<F> <{}> {}{}: {}", kind, who.empty() ? "" : who + " ", where,
                                        boundedText(cause, kEchoedParagraph));
    failure = RunFailure{kind, paragraph};
    msg().info("\n" + paragraph + "\n");
}

void RunState::recordTiming(const std::string& command, double seconds) {
    for (auto& t : timings) {
        if (t.command == command) {
            ++t.calls;
            t.seconds += seconds;
            t.peakKb = std::max(t.peakKb, peakMemoryKb());
            return;
        }
    }
    timings.push_back({command, 1, seconds, peakMemoryKb()});
}

long peakMemoryKb() {
    struct rusage usage {};
    long peak = 0;
    if (getrusage(RUSAGE_SELF, &usage) == 0) peak = usage.ru_maxrss;
    return std::max(peak, long(processPeakMb() * 1024.0));
}

}  // namespace ma
