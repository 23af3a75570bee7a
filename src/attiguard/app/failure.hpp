#pragma once
/// @file failure.hpp
/// What a program prints and returns for an exception that reached its top (docs/errors.md,
/// docs/architecture.md "Errors"): attiguard's error family maps to its exit code; running out
/// of memory or asking for a container larger than possible (std::bad_alloc,
/// std::length_error) is an input problem (exit 2) whose message says what was too large; any
/// other exception is an internal error (exit 3).

#include <exception>
#include <string>

#include "attiguard/core/errors.hpp"

namespace attiguard::app {

/// The exit code and the one-line message of a failure.
struct Failure {
  ExitCode code{ExitCode::numerical_failure};
  std::string message;
};

/// Classifies `error` (non-null). `scenario` (may be empty) is the file being processed; it is
/// named in the out-of-memory message.
[[nodiscard]] Failure describe_failure(const std::exception_ptr& error,
                                       const std::string& scenario) noexcept;

}  // namespace attiguard::app
