#pragma once
/// @file failure.hpp
/// What a program prints and returns for an exception that reached its top (docs/errors.md,
/// docs/architecture.md "Errors"): attiguard's error family maps to its exit code; running out
/// of memory or asking for a container larger than possible (std::bad_alloc,
/// std::length_error) is an input problem (exit 2) whose message says what was too large; a
/// worker thread the system refuses (parallel::ThreadStartError) is exit 2 naming --threads; any
/// other exception is an internal error (exit 3).

#include <exception>
#include <string>

#include "attiguard/core/errors.hpp"
#include "attiguard/parallel/worker_pool.hpp"
#include "attiguard/scenario/document.hpp"

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

/// "cannot start worker thread K of N (reason): the system limits …; use SETTING M or fewer"
/// for a worker thread the system refused (M: the threads that did start, at least 1); SETTING
/// is "--threads " (campaign, tune: then the flag's limit follows) or "threads = " (the
/// `[partition] threads` key of reach). docs/errors.md, "No abort".
[[nodiscard]] std::string thread_start_advice(const parallel::ThreadStartError& e,
                                              const std::string& setting);

/// The key most likely responsible for a numerical failure (a diverging run) of the scenario
/// `doc`, located and with a hint (docs/errors.md, "Numerical failures"), or "" when none stands
/// out. Looks, for kinds rigid_body and pet_erg, at a fixed step above the stability limit
/// ≈ 2/λ_max of the PD-controlled body (λ_max: the fastest eigenvalue of J_i s² + k_d s + k_p
/// over the principal moments J_i, and the gyroscopic rate |ω0| max|J_j − J_k|/J_i), and at an
/// erg.kappa that turns the reference by more than 1 rad per integrator step (κ Γ_d h > 1).
/// Never throws.
[[nodiscard]] std::string numerical_failure_hint(const scenario::Document& doc) noexcept;

/// `message` of a numerical failure of `doc`'s run followed by its hint ("; likely …"), or
/// `message` alone when there is none.
[[nodiscard]] std::string located_numerical_failure(const std::string& message,
                                                    const scenario::Document& doc) noexcept;

}  // namespace attiguard::app
