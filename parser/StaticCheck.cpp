#include "parser/StaticCheck.hpp"

#include <fmt/format.h>
#include <pybind11/embed.h>
#include <pybind11/stl.h>

#include "core/Messages.hpp"
#include "parser/Catalog.hpp"
#include "parser/ParserMessages.hpp"
#include "parser/RunState.hpp"

namespace py = pybind11;

namespace ma {

namespace {

// The syntax-tree walk. `catalog`: command -> (level, accepts context keywords); a level maps
// each keyword name to (supported, sub-level of a factor keyword or None, check of its literal
// values or None; for an unsupported keyword, the reason it is refused). Returns [(line, command, cause)] in line order.
const char* kChecker = R"PY(
import ast

_DYNAMIC = {"exec", "eval", "globals", "locals", "vars", "__import__", "setattr", "getattr", "INCLUDE"}

def _is_command_like(name):
    return any(c.isalpha() for c in name) and all(c.isupper() or c.isdigit() or c == "_" for c in name)

def _defined_names(tree):
    defined, opaque = set(), False
    for node in ast.walk(tree):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            defined.add(node.name)
        elif isinstance(node, ast.Name) and not isinstance(node.ctx, ast.Load):
            defined.add(node.id)
        elif isinstance(node, ast.arg):
            defined.add(node.arg)
        elif isinstance(node, (ast.Global, ast.Nonlocal)):
            defined.update(node.names)
        elif isinstance(node, (ast.Import, ast.ImportFrom)):
            for alias in node.names:
                if alias.name == "*":
                    opaque = opaque or getattr(node, "module", None) != "code_aster.Commands"
                else:
                    defined.add((alias.asname or alias.name).split(".")[0])
        elif isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id in _DYNAMIC:
            opaque = True
    return defined, opaque

def _unknown_keyword(path, command, where, level):
    known = ", ".join(sorted(k for k, (supported, _, _, _) in level.items() if supported))
    return "unknown keyword %s for %s (known keywords%s: %s)" % (path, command, where, known)

def _literal(node):
    try:
        value = ast.literal_eval(node)
    except Exception:
        return None
    items = list(value) if isinstance(value, (tuple, list)) else [value]
    ok = all(isinstance(x, (str, float)) or (isinstance(x, int) and not isinstance(x, bool)) for x in items)
    return items if ok and items else None

def _check_value(kw, path, command, line, level, problems, top=None):
    supported, _, checker, only_with = level[kw.arg]
    if only_with is not None and top is not None:
        name, values, default = only_with
        given = top.get(name, [default] if default is not None else None)
        if given is not None and len(given) == 1 and given[0] not in values:
            problems.append((line, command, "keyword %s is not supported by miniaster with %s='%s' (only with %s)"
                             % (path, name, given[0], " or ".join("%s='%s'" % (name, v) for v in values))))
            return
    if not supported:  # checker: the reason, as the run gives it; None stands for an absent keyword
        if not (isinstance(kw.value, ast.Constant) and kw.value.value is None):
            problems.append(
                (line, command, "keyword %s is not supported by miniaster (%s)" % (path, checker)))
        return
    items = _literal(kw.value) if checker is not None else None
    cause = checker(items, path) if items is not None else ""
    if cause:
        problems.append((line, command, cause))

def _factor_calls(value):
    items = value.elts if isinstance(value, (ast.Tuple, ast.List)) else [value]
    for i, item in enumerate(items, 1):
        if isinstance(item, ast.Call) and isinstance(item.func, ast.Name) and item.func.id == "_F":
            yield i, item

def _check_call(call, command, level, context_keywords, f_is_ours, problems):
    top = {kw.arg: _literal(kw.value) for kw in call.keywords if kw.arg is not None}
    top = {k: v for k, v in top.items() if v is not None}
    for kw in call.keywords:
        if kw.arg is None or kw.arg == "reuse":
            continue  # **kwargs: seen by the run
        if kw.arg not in level:
            if not context_keywords:
                problems.append((call.lineno, command, _unknown_keyword(kw.arg, command, "", level)))
            continue
        _check_value(kw, kw.arg, command, call.lineno, level, problems)
        sub = level[kw.arg][1]
        if sub is None or not f_is_ours:
            continue
        for i, occurrence in _factor_calls(kw.value):
            where = "%s[%d]" % (kw.arg, i)
            for fkw in occurrence.keywords:
                if fkw.arg is None:
                    continue
                if fkw.arg not in sub:
                    problems.append((call.lineno, command,
                                     _unknown_keyword(where + "/" + fkw.arg, command, " in " + where, sub)))
                else:
                    _check_value(fkw, where + "/" + fkw.arg, command, call.lineno, sub, problems, top)

def check(source, catalog, unsupported):
    try:
        tree = ast.parse(source)
    except (SyntaxError, ValueError):
        tree = ast.parse(source.decode("latin-1"))
    defined, opaque = _defined_names(tree)
    problems = []
    for node in ast.walk(tree):
        if not (isinstance(node, ast.Call) and isinstance(node.func, ast.Name)):
            continue
        name = node.func.id
        if name in defined:
            continue  # the file's own function or variable
        if name in catalog:
            level, context_keywords = catalog[name]
            _check_call(node, name, level, context_keywords, "_F" not in defined, problems)
        elif name in unsupported:
            problems.append((node.lineno, name, "command %s is not supported by miniaster" % name))
        elif not opaque and _is_command_like(name) and not hasattr(__builtins__, name):
            problems.append((node.lineno, name,
                             "unknown command %s (not a code_aster command known to miniaster)" % name))
    problems.sort(key=lambda p: p[0])
    return problems
)PY";

// The check of the literal values of a simple keyword: [str | int | float] -> "" or the cause.
py::object valueChecker(const cata::Keyword& def) {
    if (def.kind != cata::Keyword::Kind::Simple) return py::none();
    return py::cpp_function([&def](const py::list& items, const std::string& path) {
        std::vector<KeywordValue> values;
        for (const auto& item : items) {
            if (py::isinstance<py::str>(item) && def.acceptsText) values.emplace_back(item.cast<std::string>());
            else if (py::isinstance<py::int_>(item) && (def.acceptsInt || def.acceptsReal))
                values.emplace_back(def.acceptsInt ? KeywordValue(item.cast<long long>()) : item.cast<double>());
            else if (py::isinstance<py::float_>(item) && def.acceptsReal) values.emplace_back(item.cast<double>());
            else return std::string();  // a type the run reports with the value it sees
        }
        return literalValueProblem(def, values, path);
    });
}

// Keyword names of one catalog level, blocks flattened (a keyword of any block is known here; one
// that several blocks define may take other values in each: its values are left to the run).
// The default text of the command's keyword `name` (blocks included), or None.
py::object commandDefault(const std::vector<cata::Keyword>& content, const std::string& name) {
    for (const auto& k : content) {
        if (k.kind == cata::Keyword::Kind::Block) {
            if (auto d = commandDefault(k.content, name); !d.is_none()) return d;
        } else if (k.name == name && k.hasDefault() && std::holds_alternative<std::string>(k.defaultValues.front())) {
            return py::str(std::get<std::string>(k.defaultValues.front()));
        }
    }
    return py::none();
}

// (keyword of the command, its values for which `k` is supported, its default) or None.
py::object onlyWithOf(const cata::Keyword& k, const std::vector<cata::Keyword>& command) {
    if (k.onlyWithKeyword.empty()) return py::none();
    return py::make_tuple(k.onlyWithKeyword, k.onlyWithValues, commandDefault(command, k.onlyWithKeyword));
}

void addLevel(const std::vector<cata::Keyword>& content, py::dict& level, const std::vector<cata::Keyword>& command) {
    for (const auto& k : content) {
        if (k.kind == cata::Keyword::Kind::Block) {
            addLevel(k.content, level, command);
            continue;
        }
        const bool supported = k.kind != cata::Keyword::Kind::Unsupported;
        if (level.contains(k.name.c_str())) {
            py::tuple seen = level[k.name.c_str()];
            const bool either = seen[0].cast<bool>() || supported;
            level[k.name.c_str()] =
                py::make_tuple(either, seen[1], either ? py::object(py::none()) : seen[2], py::none());
            continue;
        }
        py::object sub = py::none();
        if (k.kind == cata::Keyword::Kind::Factor) {
            py::dict d;
            addLevel(k.content, d, command);
            sub = d;
        }
        // An unsupported keyword carries its reason instead of a value check.
        level[k.name.c_str()] =
            py::make_tuple(supported, sub, supported ? valueChecker(k) : py::str(k.why), onlyWithOf(k, command));
    }
}

py::dict catalogForCheck() {
    py::dict commands;
    for (const auto& [name, command] : Catalog::instance().commands()) {
        py::dict level;
        addLevel(command.content, level, command.content);
        commands[name.c_str()] = py::make_tuple(level, command.acceptsContextKeywords);
    }
    return commands;
}

}  // namespace

bool checkCommandFileStatically(const std::string& source, RunState& run) {
    std::vector<std::tuple<int, std::string, std::string>> problems;
    try {
        py::dict scope;
        scope["__builtins__"] = py::module_::import("builtins");
        py::exec(kChecker, scope);
        problems = scope["check"](py::bytes(source), catalogForCheck(), unsupportedCommands())
                       .cast<std::vector<std::tuple<int, std::string, std::string>>>();
    } catch (py::error_already_set& e) {
        // A defect of the check itself must not stop a file that may well be valid.
        msg().alarm(SUPERVIS_4, e.what());
        return true;
    }
    if (problems.empty()) return true;
    if (problems.size() == 1) {
        const auto& [line, who, cause] = problems.front();
        run.fail("ERROR", who, line, cause);
        return false;
    }
    std::string list;
    for (const auto& [line, who, cause] : problems) list += fmt::format("\n    line {}: {}: {}", line, who, cause);
    run.fail("ERROR", "", 0,
             fmt::format("{} problems found in the command file before its first command (none was run):{}",
                         problems.size(), list));
    return false;
}

}  // namespace ma
