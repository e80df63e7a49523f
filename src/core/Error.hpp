#pragma once
// Errors raised by commands. The supervisor adds the command name and the .comm line and turns
// them into the one-paragraph diagnosis and the exit status.
#include <stdexcept>
#include <string>

namespace ma {

// Bad input from the user: wrong keyword value, missing group, unreadable file...
class UserError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A documented code_aster feature that miniaster has not implemented (yet).
class NotImplemented : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The numerics failed: singular system, no convergence, NaN. Never silenced.
class NumericalError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A bug of miniaster, not of the input: e.g. a command reads a keyword that the call does not
// hold and the catalog gives no default for. Reported as an internal error naming the command.
class InternalError : public std::logic_error {
public:
    using std::logic_error::logic_error;
};

}  // namespace ma
