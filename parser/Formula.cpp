#include "parser/Formula.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <pybind11/eval.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "core/Error.hpp"
#include "core/Messages.hpp"

namespace py = pybind11;

namespace ma {

// Hidden like pybind11's own types (avoids -Wattributes on the py::object members).
struct __attribute__((visibility("hidden"))) Formula::Python {
    py::object code;       // compiled `lambda <parameters>: (<expression>)`
    py::object evaluator;  // evaluate_many below
    py::dict context;      // extra keywords of FORMULE
    py::dict commGlobals;  // the command file's namespace (live)
};

namespace {
// Python side of a formula: the expression is compiled once as `lambda <NOM_PARA>: (<VALE>)`;
// `evaluate_many` builds the function for a batch and runs the whole batch inside Python,
// reporting the index of the failing point instead of raising.
const char* kFormulaSupport = R"PY(
import builtins as _builtins
import math as _math

_MATH = {k: getattr(_math, k) for k in dir(_math) if not k.startswith("_")}

# Whole-batch evaluation with numpy arrays for the parameters. Only the math names that numpy
# implements with the same meaning are swapped; anything else (user functions with `if`,
# math.floor, min/max...) raises on arrays and the batch falls back to the point loop, which is
# also rerun whenever the vector result is not finite, so that errors carry Python's own message.
try:
    import numpy as _np
    _NUMPY_MATH = {k: getattr(_np, v) for k, v in {
        "sin": "sin", "cos": "cos", "tan": "tan", "asin": "arcsin", "acos": "arccos",
        "atan": "arctan", "atan2": "arctan2", "sinh": "sinh", "cosh": "cosh", "tanh": "tanh",
        "exp": "exp", "log10": "log10", "sqrt": "sqrt", "fabs": "fabs", "hypot": "hypot",
        "pow": "power"}.items()}
except ImportError:
    _np = None

_VECTOR_MIN = 16
_MAX_BRANCHES = 64

def _number(value):
    # float() would read a text ('0.5') as a number: a formula that returns a text is an error.
    if isinstance(value, (str, bytes, bytearray)):
        raise TypeError("the formula returns a text (%r), not a number" % (value[:40],))
    return float(value)

def _scope(context, comm_globals, math_names):
    # Name lookup, innermost first: parameters, context objects, math, the command file's globals
    # (read at each batch, so that pre-2018 files see the functions they define).
    g = dict(comm_globals)
    g.update(math_names)
    g.update(context)
    g["__builtins__"] = _builtins
    return g

if _np is not None:
    class _Split(BaseException):
        # Raised by the truth value of a condition that differs between points; BaseException so
        # that a user's `except Exception` does not swallow it.
        def __init__(self, mask):
            self.mask = mask

    class _PointArray(_np.ndarray):
        # The parameters' arrays. Arithmetic and comparisons keep the type; asking for a truth
        # value (`if`, `and`, `or`, min/max, a conditional expression) gives the common value of
        # all points, or raises _Split with the condition's mask when the points disagree.
        def __bool__(self):
            mask = _np.asarray(self, dtype=bool)
            if mask.ndim != 1:
                raise TypeError("not a per-point condition")
            if mask.all():
                return True
            if not mask.any():
                return False
            raise _Split(mask)

def _branches(f, columns, n, budget):
    # f on the points of `columns` (plain arrays of length n): the whole set when every condition
    # f meets holds or fails on all points alike, else each side of the first disagreeing
    # condition on its own, recursively. Returns (values, list of (index array, branch)) or None.
    try:
        with _np.errstate(all="ignore"):
            r = f(*[c.view(_PointArray) for c in columns])
        r = _np.asarray(r)
        if r.dtype.kind not in "biuf":
            return None  # texts, objects: the point loop names them
        r = r.astype(float)
    except _Split as split:
        mask = split.mask
        if mask.shape != (n,) or budget[0] <= 1:
            return None
        budget[0] -= 1
        out = _np.empty(n)
        leaves = []
        for side in (mask, ~mask):
            index = _np.flatnonzero(side)
            sub = _branches(f, [c[index] for c in columns], len(index), budget)
            if sub is None:
                return None
            out[index] = sub[0]
            leaves += [index[i] for i in sub[1]]
        return out, leaves
    except Exception:
        return None
    if r.shape == ():
        r = _np.full(n, float(r))
    if r.shape != (n,):
        return None
    return r, [_np.arange(n)]

def _evaluate_vector(code, context, comm_globals, array, npar, n):
    # (values, branches) or None. The points of each branch are checked at their first and last
    # point against the scalar evaluation: a function that is not evaluated point by point on
    # arrays (indexing, reductions...) falls back to the point loop.
    math_names = dict(_MATH)
    math_names.update(_NUMPY_MATH)
    try:
        f = eval(code, _scope(context, comm_globals, math_names))
    except Exception:
        return None
    result = _branches(f, [_np.ascontiguousarray(array[:, j]) for j in range(npar)], n, [_MAX_BRANCHES])
    if result is None:
        return None
    r, leaves = result
    if not _np.isfinite(r).all():
        return None
    scalar = eval(code, _scope(context, comm_globals, _MATH))
    tolerance = 1e-12 * float(_np.max(_np.abs(r)))
    try:
        for index in leaves:
            for i in (index[0], index[-1]):
                if abs(_number(scalar(*array[i].tolist())) - r[i]) > tolerance:
                    return None
    except Exception:
        return None
    return r, len(leaves)

def _distinct_rows(array):
    # (distinct rows, inverse) when repeated points make it worth it, else (array, None).
    distinct, inverse = _np.unique(array, axis=0, return_inverse=True)
    if len(distinct) > 0.8 * len(array):
        return array, None
    return distinct, inverse.reshape(-1)

def evaluate_many(code, context, comm_globals, array, npar):
    # `array`: numpy (n, npar) array when numpy is there, else a flat list. Returns (values,
    # failing index or -1, Python's message, path: "vector:<branches>", "points:<evaluated>").
    if _np is not None:
        n = array.shape[0]
        if n >= _VECTOR_MIN:
            v = _evaluate_vector(code, context, comm_globals, array, npar, n)
            if v is not None:
                return v[0], -1, "", "vector:%d" % v[1]
        f = eval(code, _scope(context, comm_globals, _MATH))
        if npar > 0:
            # Once per distinct point, without a Python-level loop (_number() of each value as
            # below); on any error the loop below runs again for the failing index and Python's
            # own message.
            points, inverse = _distinct_rows(array) if n >= _VECTOR_MIN else (array, None)
            try:
                r = _np.fromiter(map(_number, map(f, *[points[:, j].tolist() for j in range(npar)])),
                                 dtype=float, count=len(points))
                return (r if inverse is None else r[inverse]), -1, "", "points:%d" % len(points)
            except Exception:
                pass
        rows = array.tolist()
    else:
        n = len(array) // npar if npar else 1
        rows = [array[i * npar:(i + 1) * npar] for i in range(n)]
        f = eval(code, _scope(context, comm_globals, _MATH))
    out = [0.0] * n
    i = 0
    try:
        for i in range(n):
            out[i] = _number(f(*rows[i]))
    except Exception as e:
        return None, i, "%s: %s" % (type(e).__name__, e), "points:%d" % n
    return out, -1, "", "points:%d" % n
)PY";

// Leaked on purpose: a static py::object would be released after the interpreter is gone.
py::module_& supportModule() {
    static py::module_* module = [] {
        auto* m = new py::module_(py::module_::import("types").attr("ModuleType")("_miniaster_formula"));
        py::dict ns = m->attr("__dict__");
        ns["__builtins__"] = py::module_::import("builtins");
        py::exec(kFormulaSupport, ns);
        return m;
    }();
    return *module;
}

// numpy lets a whole batch go through Python as one array (see kFormulaSupport).
bool numpyAvailable() { return !supportModule().attr("_np").is_none(); }

bool isIdentifier(const std::string& s) { return py::str(s).attr("isidentifier")().cast<bool>(); }
}  // namespace

Formula::Formula(std::string expression, std::vector<std::string> parameters, py::dict context, py::dict commGlobals,
                 std::string commFile, int line)
    : parameters_(std::move(parameters)), commFile_(std::move(commFile)), line_(line) {
    // code_aster joins multi-line texts and strips them.
    for (char c : expression) expression_ += (c == '\n' || c == '\r') ? ' ' : c;
    const auto first = expression_.find_first_not_of(" \t");
    expression_ =
        first == std::string::npos ? "" : expression_.substr(first, expression_.find_last_not_of(" \t") - first + 1);
    if (expression_.empty()) throw UserError("FORMULE: VALE is empty");
    for (const auto& p : parameters_)
        if (!isIdentifier(p)) throw UserError(fmt::format("FORMULE: NOM_PARA '{}' is not a valid parameter name", p));
    python_ = std::make_unique<Python>();
    auto builtins = py::module_::import("builtins");
    try {
        builtins.attr("compile")(expression_, "<FORMULE>", "eval");  // the expression alone, for the message
        std::string lambda = "lambda ";
        for (size_t i = 0; i < parameters_.size(); ++i) lambda += (i ? ", " : "") + parameters_[i];
        lambda += ": (" + expression_ + "\n)";
        python_->code = builtins.attr("compile")(lambda, "<FORMULE>", "eval");
    } catch (py::error_already_set& e) {
        throw UserError(fmt::format("FORMULE: VALE '{}' is not a valid Python expression ({})", expression_, e.what()));
    }
    auto& support = supportModule();
    python_->context = context;
    python_->commGlobals = commGlobals;
    python_->evaluator = support.attr("evaluate_many");
}

Formula::~Formula() {
    // The interpreter is never finalised during a run; after it, leak rather than crash.
    if (!python_) return;
    if (!Py_IsInitialized()) {
        python_->code.release();
        python_->evaluator.release();
        python_->context.release();
        python_->commGlobals.release();
        return;
    }
    py::gil_scoped_acquire gil;
    python_.reset();
}

void Formula::fail(std::span<const double> args, const std::string& why) const {
    std::string values;
    for (size_t j = 0; j < parameters_.size() && j < args.size(); ++j)
        values += fmt::format("{}{}={}", j ? ", " : "", parameters_[j], args[j]);
    throw UserError(fmt::format("formula {} = '{}' (FORMULE defined in {}, line {}) failed for {}: {}",
                                name.empty() ? "<unnamed>" : name, expression_,
                                std::filesystem::path(commFile_).filename().string(), line_,
                                values.empty() ? "no parameter" : values, why));
}

void Formula::logPath(const std::string& path, size_t npoints) const {
    const auto colon = path.find(':');
    const std::string kind = path.substr(0, colon);
    if (kind == loggedPath_) return;
    loggedPath_ = kind;
    const long count = std::stol(path.substr(colon + 1));
    if (kind == "vector")
        msg().infof("    FORMULE {}: evaluated on numpy arrays, {} points per batch{}",
                    name.empty() ? expression_ : name, npoints,
                    count > 1
                        ? fmt::format(" (its conditions split the points into {} branches, each on arrays)", count)
                        : std::string());
    else
        msg().infof(
            "    FORMULE {}: numpy arrays do not go through its expression: Python is called once per distinct "
            "point ({} of {} points in the first batch)",
            name.empty() ? expression_ : name, count, npoints);
}

double Formula::evaluate(std::span<const double> args) const { return evaluateMany(args, 1).at(0); }

std::vector<double> Formula::evaluateMany(std::span<const double> args, size_t npoints) const {
    const size_t np = parameters_.size();
    if (args.size() != npoints * np)
        throw UserError(fmt::format("formula {} expects {} parameter(s) ({}), got {} value(s) per point", name, np,
                                    fmt::join(parameters_, ", "), npoints ? args.size() / npoints : args.size()));
    if (npoints == 0) return {};
    py::gil_scoped_acquire gil;
    py::object batch;
    if (numpyAvailable()) {
        py::array_t<double> array({npoints, np});
        std::copy(args.begin(), args.end(), array.mutable_data());
        batch = std::move(array);
    } else {
        py::list values(args.size());
        for (size_t i = 0; i < args.size(); ++i) values[i] = py::float_(args[i]);
        batch = std::move(values);
    }
    py::tuple result = python_->evaluator(python_->code, python_->context, python_->commGlobals, batch, np);
    const long failed = result[1].cast<long>();
    if (failed >= 0) fail(args.subspan(size_t(failed) * np, np), result[2].cast<std::string>());
    if (npoints >= kBatchLogged) logPath(result[3].cast<std::string>(), npoints);
    std::vector<double> out(npoints);
    if (py::isinstance<py::array>(result[0])) {
        auto values = result[0].cast<py::array_t<double, py::array::c_style | py::array::forcecast>>();
        std::copy(values.data(), values.data() + npoints, out.begin());
    } else {
        out = result[0].cast<std::vector<double>>();
    }
    for (size_t i = 0; i < out.size(); ++i)
        if (!std::isfinite(out[i]))
            fail(args.subspan(i * np, np),
                 std::isnan(out[i]) ? "the result is nan" : fmt::format("the result is {}", out[i]));
    return out;
}

}  // namespace ma
