#pragma once
/// @file robust_margin_setup.hpp
/// `[control] margins = "robust"` of the `pet_erg` kind (docs/pet-erg.md, section 13;
/// docs/scenario-format.md, "pet_erg"): the robust margin computed offline from the scenario's
/// bounds, and the refusal of a scenario whose bounds leave no admissible set.

#include <string>

#include "attiguard/governor/attitude_governor.hpp"
#include "attiguard/scenario/table_reader.hpp"
#include "attiguard/sim/pet_erg_scenario.hpp"

namespace attiguard::scenario {

/// Computes sc.params.robust and the reduced torque limits (sc.robust_tau_max,
/// sc.robust_polytope_gamma_d) from the flight loop, [imperfections] and [[wheels]] of `sc`
/// (docs/pet-erg.md, section 13). Fails at control.margins (or control.robust_reference_step)
/// when the bounds leave no admissible set: the command error reaches a torque limit, or
/// Γ_min ≥ (1 − δ) Γ_d' (the reduced torque threshold).
void set_robust_margins(const TableReader& control, sim::PetErgScenario& sc);

/// Robust admissibility of the targets (docs/pet-erg.md, section 13): every desired attitude has
/// Γ_W(R_d) > Γ_min, else the reference could never reach it. Fails at desired.attitude (or
/// desired.schedule) with the numbers.
void check_robust_desired(const TableReader& desired, const governor::AttitudeGovernor& gov,
                          const sim::PetErgScenario& sc);

/// Robust admissibility of the initial state (section 13): Γ_W(R_g(0)) > Γ_min and
/// W(0) + start allowance ≤ Γ_W(R_g(0)). Returns the reason when it fails, else "".
[[nodiscard]] std::string robust_initial_problem(const governor::AttitudeGovernor& gov,
                                                 const sim::PetErgScenario& sc);

}  // namespace attiguard::scenario
