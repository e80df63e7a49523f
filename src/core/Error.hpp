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

// The linear solver found the system singular (null pivot, NaN or Inf in the solution): callers
// that know a likely cause (e.g. ContactLoop, a huge penalty) add it by this type.
class SingularSystemError : public NumericalError {
public:
    using NumericalError::NumericalError;
};

// The Newton loop did not reach its criteria within ITER_GLOB_MAXI iterations (ARRET='OUI').
class NonConvergenceError : public NumericalError {
public:
    using NumericalError::NumericalError;
};

// A bug of miniaster, not of the input: e.g. a command reads a keyword that the call does not
// hold and the catalog gives no default for. Reported as an internal error naming the command.
class InternalError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace ma
