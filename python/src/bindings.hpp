#pragma once
/// @file bindings.hpp
/// The parts of the Python extension module `attiguard._core` (docs/python.md), one per file.

#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include <pybind11/pybind11.h>

#include "attiguard/core/errors.hpp"

namespace attiguard::python {

/// The time checks of a flight-loop object's step() (docs/python.md, "Validation"): reset first
/// (`reset_call` names it), t finite and not before the previous call's `last_t`. Throws
/// InputError labelled `label`.
inline void check_step_time(const char* label, const char* reset_call, bool started, double t,
                            double last_t) {
  if (!started) throw InputError(std::string(label) + ": call " + reset_call + " before the first step()");
  if (!std::isfinite(t)) throw InputError(std::string(label) + ": t: must be finite");
  if (t < last_t) {
    std::array<char, 96> buf{};
    std::snprintf(buf.data(), buf.size(), "%.17g s < %.17g s", t, last_t);
    throw InputError(std::string(label) + ": t: time went backwards (t = " + buf.data() +
                     " of the previous call)");
  }
}

/// attiguard::Error and its subclasses as Python exceptions with the CLI's messages
/// (docs/conventions.md, "Exit codes").
void bind_errors(pybind11::module_& m);
/// SO(3) and quaternion helpers (conventions: hat, exp, log, φ, d; [Waypoint eqs. (1), (12)]).
void bind_lie(pybind11::module_& m);
/// Scenario runs: `attiguard run` / `check` / `reach` on a scenario file or a dict; run() fills
/// numpy arrays through a row sink (bind_run.cpp).
void bind_run(pybind11::module_& m);
/// PET-ERG governor [PET-ERG eqs. (3)-(6)], PD law [PET-ERG eq. (3)] and the rigid body.
void bind_governor(pybind11::module_& m);
/// Waypoint guidance [Waypoint Alg. 1] and the quaternion PID [Waypoint eq. (27)].
void bind_guidance(pybind11::module_& m);
/// The slew planner (docs/slew-planner.md): _plan_slew returns the plan as numpy arrays.
void bind_plan(pybind11::module_& m);
/// The planned mode's governor in a user's loop (docs/pet-erg.md, section 16.2).
void bind_planned(pybind11::module_& m);

}  // namespace attiguard::python
