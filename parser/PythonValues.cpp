#include "parser/PythonValues.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

#include "core/Error.hpp"

namespace py = pybind11;

namespace ma {

namespace {

// A keyword's value is a scalar, a list of them or _F occurrences holding those: a few levels. A
// deeper value, or one that contains itself, is refused before it is walked (a value nested 1e5
// deep overflowed the stack; a list that holds itself never ended).
constexpr size_t kMaxValueDepth = 32;

CallValue toCallValue(py::handle h, const std::string& keyword, std::vector<PyObject*>& path);

CallValue containerToCallValue(py::handle h, const std::string& keyword, std::vector<PyObject*>& path) {
    const std::string what = keyword.empty() ? "a value" : "the value of " + keyword;
    if (std::find(path.begin(), path.end(), h.ptr()) != path.end())
        throw UserError(what + " contains itself (a list, tuple or _F that holds itself): it has no end");
    if (path.size() >= kMaxValueDepth)
        throw UserError(
            fmt::format("{} is nested more than {} levels deep (lists, tuples or _F inside each other); "
                        "a keyword takes a value, a list of values or _F occurrences",
                        what, kMaxValueDepth));
    path.push_back(h.ptr());
    CallValue v;  // filled below, then the path is left
    if (PyDict_Check(h.ptr())) {
        std::vector<std::pair<std::string, CallValue>> d;
        for (auto [k, val] : h.cast<py::dict>())
            d.emplace_back(py::str(k).cast<std::string>(), toCallValue(val, keyword, path));
        v = CallValue::factor(std::move(d));
    } else {
        std::vector<CallValue> items;
        for (auto item : h) items.push_back(toCallValue(item, keyword, path));
        v = CallValue::list(std::move(items));
    }
    path.pop_back();
    return v;
}

CallValue toCallValue(py::handle h, const std::string& keyword, std::vector<PyObject*>& path) {
    CallValue v;
    if (h.is_none()) return v;
    if (PyBool_Check(h.ptr())) {
        v.kind = CallValue::Kind::Bool;
        v.integer = h.cast<bool>() ? 1 : 0;
        return v;
    }
    if (PyLong_Check(h.ptr())) {
        int overflow = 0;
        long long i = PyLong_AsLongLongAndOverflow(h.ptr(), &overflow);
        if (!overflow) return CallValue::of(i);
        v.kind = CallValue::Kind::Other;
        v.text = "int (too large)";
        return v;
    }
    if (PyFloat_Check(h.ptr())) return CallValue::of(h.cast<double>());
    if (PyUnicode_Check(h.ptr())) return CallValue::of(h.cast<std::string>());
    if (py::isinstance<ConceptHandle>(h)) return CallValue::of(h.cast<ConceptHandle&>().object);
    if (PyList_Check(h.ptr()) || PyTuple_Check(h.ptr()) || PyDict_Check(h.ptr()))
        return containerToCallValue(h, keyword, path);
    // numpy scalars and the like.
    if (py::hasattr(h, "__index__"))
        return CallValue::of(static_cast<long long>(h.attr("__index__")().cast<long long>()));
    if (py::hasattr(h, "__float__") && !py::hasattr(h, "__len__"))
        return CallValue::of(h.attr("__float__")().cast<double>());
    v.kind = CallValue::Kind::Other;
    v.text = py::str(py::type::handle_of(h).attr("__name__")).cast<std::string>();
    return v;
}

}  // namespace

CallValue toCallValue(py::handle h, const std::string& keyword) {
    std::vector<PyObject*> path;
    return toCallValue(h, keyword, path);
}

}  // namespace ma
