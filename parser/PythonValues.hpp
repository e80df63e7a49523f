#pragma once
// Python values of a command call -> CallValue (the catalogue's input): scalars, lists, _F
// occurrences and the opaque concept objects handed to Python.
#include <pybind11/pybind11.h>

#include <string>

#include "core/Concept.hpp"
#include "parser/Catalog.hpp"

namespace ma {

// A concept as Python sees it: opaque, callable when it is a function (FORMULE, DEFI_FONCTION).
struct ConceptHandle {
    ConceptPtr object;
};

// The value of `keyword` (named in the errors: UserError for a value nested too deep or holding itself).
CallValue toCallValue(pybind11::handle h, const std::string& keyword = "");

}  // namespace ma
