#pragma once
/// @file pet_erg_slew_problem.hpp
/// The slew of a pet_erg scenario as the planner's problem (docs/slew-planner.md, "The
/// problem"; `attiguard plan`): R_0 and the desired attitude, J, the cones and `[plan]`; the
/// torque limit is the PD law's torque scale of the defaults, min(τ_max, the wheel polytope's
/// inscribed radius) − the disturbance bound (docs/pet-erg.md, section 8).

#include "attiguard/plan/slew_problem.hpp"
#include "attiguard/sim/pet_erg_scenario.hpp"

#include <optional>
#include <string>

namespace attiguard::sim {

/// Why `sc` is not one rest-to-rest slew the planner can plan, at which key.
struct SlewRefusal {
  std::string table;    ///< "desired", "initial"
  std::string key;      ///< "attitude", "omega_b", "schedule"
  std::string message;  ///< one line
};

/// What the start may be.
enum class SlewStart {
  at_rest,  ///< `attiguard plan`: the plan is the whole slew, from rest
  /// governor = "planned": the plan starts at rest at R_0 and a non-zero ω_0 is a start off the
  /// plan, which the clock waits out (docs/pet-erg.md, section 16.1, "No deadlock")
  any_rate,
};

/// Why `sc` is no single rest-to-rest slew (a schedule of several attitudes, a non-zero initial
/// rate when `start` is at_rest, a target equal to the start), or nullopt (docs/slew-planner.md,
/// "Failures").
[[nodiscard]] std::optional<SlewRefusal> slew_refusal(const PetErgScenario& sc,
                                                      SlewStart start = SlewStart::at_rest);

/// The planner's problem of `sc` (docs/slew-planner.md, "The problem"): from R_0 at rest. Throws
/// SetupError with slew_refusal's message when there is one.
[[nodiscard]] plan::SlewProblem slew_problem(const PetErgScenario& sc,
                                             SlewStart start = SlewStart::at_rest);

/// The planner's options of `sc` (`[plan] intervals`; docs/slew-planner.md, "Options").
[[nodiscard]] plan::PlannerOptions planner_options(const PetErgScenario& sc);

}  // namespace attiguard::sim
