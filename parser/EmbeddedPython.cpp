#include "parser/EmbeddedPython.hpp"

#include <pybind11/embed.h>

#include <cstdlib>
#include <exception>

namespace py = pybind11;

namespace ma {

std::string pythonHomeNote() {
    const char* home = std::getenv("PYTHONHOME");
    if (!home || std::string(home) == MINIASTER_PYTHON_HOME) return "";
    return std::string("Python      : ") + MINIASTER_PYTHON_HOME + " (the build's); PYTHONHOME=" + home + " is ignored";
}

std::optional<std::string> startEmbeddedPython() {
    PyConfig config;
    PyConfig_InitPythonConfig(&config);
    config.write_bytecode = 0;  // no __pycache__ beside the modules a command file imports
    // An explicit home wins over PYTHONHOME; the program name is the build's interpreter, so
    // no pyvenv.cfg of a python3 found on PATH is read.
    PyStatus status = PyConfig_SetBytesString(&config, &config.home, MINIASTER_PYTHON_HOME);
    if (!PyStatus_Exception(status))
        status = PyConfig_SetBytesString(&config, &config.program_name, MINIASTER_PYTHON_EXECUTABLE);
    if (PyStatus_Exception(status)) {
        PyConfig_Clear(&config);
        return std::string("cannot configure the embedded Python: ") + (status.err_msg ? status.err_msg : "");
    }
    try {
        py::initialize_interpreter(&config);  // clears the configuration
    } catch (const std::exception& e) {
        const char* path = std::getenv("PYTHONPATH");
        return std::string("the embedded Python (home ") + MINIASTER_PYTHON_HOME + ") cannot start: " + e.what() +
               (path ? std::string(" (PYTHONPATH=") + path + ": does it hold another Python's standard library?)" : "");
    }
    return std::nullopt;
}

}  // namespace ma
