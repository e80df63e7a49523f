#pragma once
// The embedded interpreter is the Python miniaster was built with (its home is fixed at configure
// time: /usr for Debian's /usr/bin/python3), whatever `python3` comes first on PATH (a venv or
// pyenv without numpy) and whatever PYTHONHOME says (ignored, and said in the .mess).
// PYTHONPATH and the user's site-packages are honoured: code_aster users keep their own modules
// there.
#include <optional>
#include <string>

namespace ma {

// The .mess header line about a PYTHONHOME that is ignored ("" when there is none).
std::string pythonHomeNote();
// Starts the interpreter; the reason when it cannot start (e.g. a PYTHONPATH holding another
// Python's standard library).
std::optional<std::string> startEmbeddedPython();

}  // namespace ma
