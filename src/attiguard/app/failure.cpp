#include "attiguard/app/failure.hpp"

#include <new>
#include <stdexcept>

namespace attiguard::app {

namespace {

/// "FILE: " or "".
std::string prefix(const std::string& scenario) { return scenario.empty() ? "" : scenario + ": "; }

constexpr const char* kWhatIsLarge =
    "the scenario asks for more than this machine can hold: reduce what scales the memory "
    "(simulation duration over output_interval or control_period, partition cells, soundness "
    "samples, output.boundary_points, campaign runs)";

}  // namespace

Failure describe_failure(const std::exception_ptr& error, const std::string& scenario) noexcept {
  try {
    try {
      std::rethrow_exception(error);
    } catch (const Error& e) {
      return {e.code(), e.what()};
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
