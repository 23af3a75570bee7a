#include "attiguard/app/failure.hpp"

#include <algorithm>
#include <new>
#include <stdexcept>

#include "attiguard/app/kinds.hpp"
#include "attiguard/parallel/thread_limit.hpp"
#include "attiguard/parallel/worker_pool.hpp"

namespace attiguard::app {

namespace {

/// "FILE: " or "".
std::string prefix(const std::string& scenario) { return scenario.empty() ? "" : scenario + ": "; }

constexpr const char* kWhatIsLarge =
    "the scenario asks for more than this machine can hold: reduce what scales the memory "
    "(simulation duration over output_interval or control_period, partition cells, soundness "
    "samples, output.boundary_points, campaign runs)";

/// The hint of the document's kind (its registry entry, app/kinds.hpp); "" for a kind without.
std::string hint_of(const scenario::Document& doc) {
  const KindHandler& handler = handler_for(doc);
  return handler.numerical_hint != nullptr ? handler.numerical_hint(doc) : std::string();
}

}  // namespace

std::string numerical_failure_hint(const scenario::Document& doc) noexcept {
  try {
    return hint_of(doc);
  } catch (...) {  // the scenario was valid when it ran; a hint is only a hint
    return "";
  }
}

std::string located_numerical_failure(const std::string& message,
                                      const scenario::Document& doc) noexcept {
  try {
    const std::string hint = numerical_failure_hint(doc);
    return hint.empty() ? message : message + "; likely " + hint;
  } catch (...) {
    return message;
  }
}

std::string thread_start_advice(const parallel::ThreadStartError& e, const std::string& setting) {
  std::string m = std::string(e.what()) +
                  ": the system limits the threads of this process (ulimit -u) or the memory of "
                  "their stacks (ulimit -s, ulimit -v); use " + setting +
                  std::to_string(std::max(1L, e.started())) + " or fewer";
  if (setting == "--threads ") {
    m += " (the flag takes at most " + std::to_string(parallel::thread_limit()) + " on this machine)";
  }
  return m;
}

Failure describe_failure(const std::exception_ptr& error, const std::string& scenario) noexcept {
  try {
    try {
      std::rethrow_exception(error);
    } catch (const Error& e) {
      return {e.code(), e.what()};
    } catch (const parallel::ThreadStartError& e) {
      return {ExitCode::invalid_input, prefix(scenario) + "--threads: " + thread_start_advice(e, "--threads ")};
    } catch (const std::bad_alloc&) {
      return {ExitCode::invalid_input, prefix(scenario) + "out of memory: " + kWhatIsLarge};
    } catch (const std::length_error& e) {
      return {ExitCode::invalid_input, prefix(scenario) + "a size is too large (" +
                                           std::string(e.what()) + "): " + kWhatIsLarge};
    } catch (const std::exception& e) {
      return {ExitCode::numerical_failure, std::string("internal error: ") + e.what()};
    } catch (...) {
      return {ExitCode::numerical_failure, "internal error: unknown exception"};
    }
  } catch (...) {  // building a message ran out of memory itself
    return {ExitCode::invalid_input, {}};
  }
}

}  // namespace attiguard::app
