#pragma once
/// @file interruption.hpp
/// SIGINT and SIGTERM end a command cleanly (docs/conventions.md, "Outputs"; docs/errors.md,
/// "Failed and interrupted runs"): the handler only records the signal (one lock-free atomic
/// store, async-signal-safe); the command checks the record between output rows, campaign runs
/// and analysis stages and turns it into an `Interrupted` error (exit 3), so that its output
/// folder is left with `.partial` files and a status file, never with complete-looking results.

#include <atomic>
#include <string>

#include "attiguard/core/errors.hpp"

namespace attiguard::io {

/// The error of a command stopped by SIGINT or SIGTERM: exit code 3 (the command did not finish,
/// docs/conventions.md "Exit codes").
class Interrupted : public NumericalError {
 public:
  using NumericalError::NumericalError;
};

/// Installs the handlers of SIGINT and SIGTERM (the `attiguard` program does, at its start). The
/// first signal sets the flag; a second one while the flag is set ends the process at once by
/// that signal (the escape from a command that does not reach its next check; docs/conventions.md,
/// "Outputs", point 4).
void install_interruption_handlers() noexcept;

/// True once SIGINT or SIGTERM was received (always false without the handlers;
/// docs/conventions.md, "Outputs", point 4).
[[nodiscard]] bool interrupted() noexcept;

/// The flag itself, for loops that stop picking new work when it becomes true
/// (app::run_many; docs/campaigns.md, "Interruption and resume").
[[nodiscard]] const std::atomic<bool>& interruption_flag() noexcept;

/// "SIGINT" or "SIGTERM": the signal received ("" when none), for the error line
/// (docs/conventions.md, "Outputs", point 4).
[[nodiscard]] std::string interruption_signal_name();

/// Throws Interrupted("interrupted by SIGTERM" + `what`) when a signal was received: a check point
/// of docs/conventions.md, "Outputs", point 4.
void throw_if_interrupted(const std::string& what = {});

}  // namespace attiguard::io
