#pragma once
/// @file errors.hpp
/// Error types and the CLI exit codes they map to (docs/conventions.md, "Exit codes").
///
/// These are thrown only by set-up, I/O and analysis code; flight-loop code (controllers,
/// governor, guidance step) never throws. Every error of the library is one of these (set-up
/// errors are SetupError, an InputError), so that a program maps each to its exit code.

#include <stdexcept>
#include <string>

namespace attiguard {

/// Documented exit codes of the `attiguard` program.
enum class ExitCode : int {
  ok = 0,
  invalid_input = 2,        ///< scenario file or command-line arguments are invalid
  numerical_failure = 3,    ///< solver failure, divergence, NaN detected
  verification_failed = 4,  ///< a requested safety verification failed or could not be proved
};

/// Base of attiguard's errors: a one-line message and the exit code it maps to.
class Error : public std::runtime_error {
 public:
  Error(ExitCode code, const std::string& message) : std::runtime_error(message), code_(code) {}
  [[nodiscard]] ExitCode code() const noexcept { return code_; }

 private:
  ExitCode code_;
};

/// Invalid input: the message names the file, line, column and key path where known.
class InputError : public Error {
 public:
  explicit InputError(const std::string& message) : Error(ExitCode::invalid_input, message) {}
};

/// A bad set-up parameter given to a library constructor or set-up function (a gain that is not
/// positive, an impossible cone, an invalid inertia): an InputError without a file location. The
/// scenario parsers catch it and rethrow it located at the key the value came from
/// (docs/architecture.md, "Errors"); from a program it maps to exit code 2 like any InputError.
class SetupError : public InputError {
 public:
  explicit SetupError(const std::string& message) : InputError(message) {}
};

/// Numerical failure: NaN, divergence, solver failure.
class NumericalError : public Error {
 public:
  explicit NumericalError(const std::string& message)
      : Error(ExitCode::numerical_failure, message) {}
};

/// A requested safety verification failed or could not be proved.
class VerificationFailure : public Error {
 public:
  explicit VerificationFailure(const std::string& message)
      : Error(ExitCode::verification_failed, message) {}
};

}  // namespace attiguard
