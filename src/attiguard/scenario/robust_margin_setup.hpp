#pragma once
/// @file robust_margin_setup.hpp
/// The governor's design of a `pet_erg` scenario, located (docs/pet-erg.md, sections 12-13;
/// docs/scenario-format.md, "pet_erg"): governor::design computes it, this file only locates its
/// refusals at the keys of the file and checks the robust admissibility of the targets and the
/// start.

#include <string>

#include "attiguard/governor/attitude_governor.hpp"
#include "attiguard/governor/governor_design.hpp"
#include "attiguard/scenario/table_reader.hpp"
#include "attiguard/sim/pet_erg_scenario.hpp"

namespace attiguard::scenario {

/// sim::design_governor(sc) (governor::design, docs/pet-erg.md, sections 12-13), its refusals
/// located at control.margins: with margins = "robust" the bounds that leave no admissible set
/// (the command error reaching a torque limit, Γ_min ≥ (1 − δ) Γ_d', a cone without room). The
/// wheels' own refusals are located at [[wheels]] before (parse_wheels).
[[nodiscard]] governor::GovernorDesign located_design(const TableReader& control, const sim::PetErgScenario& sc);

/// Robust admissibility of the targets (docs/pet-erg.md, section 13): every desired attitude lies
/// outside the widened repulsive bands of design.cones and has Γ_W(R_d) > Γ_min, else the
/// reference could never reach it. Fails at desired.attitude (or desired.schedule) with the
/// numbers. `design` has robust margins.
void check_robust_desired(const TableReader& desired, const governor::AttitudeGovernor& gov,
                          const sim::PetErgScenario& sc, const governor::GovernorDesign& design);

/// Robust admissibility of the initial state (section 13) for the robust margin `m`:
/// Γ_W(R_g(0)) > Γ_min and W(0) + start allowance ≤ Γ_W(R_g(0)). Returns the reason when it fails,
/// else "".
[[nodiscard]] std::string robust_initial_problem(const governor::AttitudeGovernor& gov,
                                                 const sim::PetErgScenario& sc, const governor::RobustMargin& m);

}  // namespace attiguard::scenario
