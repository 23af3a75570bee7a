#pragma once
/// @file planned_run.hpp
/// Simulation of a `pet_erg` scenario with `governor = "planned"` (docs/pet-erg.md, section
/// 16.2): the slew planned at set-up (plan/slew_planner.hpp), then flown by the tracking law with
/// feedforward under the progress governor (governor/planned_governor.hpp), in the
/// continuous-time loop (control_period = 0) or the flight loop (control_period > 0, with the
/// imperfections of section 11 and the wheels of section 12).

#include <functional>
#include <string>
#include <utility>

#include "attiguard/core/errors.hpp"

#include "attiguard/governor/planned_governor.hpp"
#include "attiguard/plan/slew_planner.hpp"
#include "attiguard/sim/pet_erg_run.hpp"

namespace attiguard::sim {

/// A planned scenario refused at set-up at one of its keys (known only once the slew is
/// planned): the application layer locates it in the file (scenario::fail_in_table).
class PlannedSetupRefusal : public SetupError {
 public:
  PlannedSetupRefusal(std::string table, std::string key, const std::string& message)
      : SetupError(table + "." + key + ": " + message), table_(std::move(table)), key_(std::move(key)),
        message_(message) {}
  [[nodiscard]] const std::string& table() const noexcept { return table_; }
  [[nodiscard]] const std::string& key() const noexcept { return key_; }
  [[nodiscard]] const std::string& message() const noexcept { return message_; }

 private:
  std::string table_, key_, message_;
};

/// What a planned run flies with (docs/pet-erg.md, section 16.2, "Defaults"): the planner's
/// problem and plan, the governor's parameters, the figures of the set-up, and the scenario as
/// run (its sampling period T_s and, when derived, its integration step set for the tracking
/// loop).
struct PlannedSetup {
  PetErgScenario run;
  plan::SlewProblem problem;
  plan::PlannedSlew planned;
  governor::PlannedGovernorParams params;
  PlannedFigures figures;
};

/// Plans the slew of `sc` and derives what the scenario leaves out from the craft
/// (docs/pet-erg.md, section 16.2, "Defaults"): the tracking gains (ω_n = 10π/T_bb capped by the
/// loop period, k_R = J_max ω_n², k_Ω = 1.6 J_max ω_n), the plan's cone margin, T_s. Throws
/// SetupError for a scenario that is no single slew, PlannedSetupRefusal for a control period
/// longer than a tenth of the plan, and the planner's VerificationFailure
/// (exit 4) or NumericalError (exit 3).
[[nodiscard]] PlannedSetup planned_setup(const PetErgScenario& sc);

/// `check`'s report of a planned scenario (docs/pet-erg.md, section 16.2, "Defaults"): the plan
/// (duration, ratio to the eigenaxis bang-bang time), the tracking gains, headroom, cone margin
/// and T_s, each marked given or derived.
[[nodiscard]] std::string planned_report(const PlannedSetup& setup);

/// Called at t = 0 and at every output instant with the state, R_d, the figures' view of the
/// instant (GovernorOutput: torque, R_g = the plan's attitude R_p(σ), V, Γ_g, margins) and the
/// planned governor's output (σ, ṡ, …).
using PlannedRowObserver =
    std::function<void(double t, const PetErgState& y, const lie::Mat3& R_d,
                       const governor::GovernorOutput& out, const governor::PlannedOutput& planned)>;

/// Simulates the planned mode of `sc` (docs/pet-erg.md, section 16.2); the result's `planned`
/// holds the plan and progress figures. Throws as planned_setup, NumericalError on divergence.
[[nodiscard]] PetErgResult simulate_planned(const PetErgScenario& sc,
                                            const PlannedRowObserver& on_output = {});

/// simulate_planned with a PET-ERG row observer (the planned output not passed on).
[[nodiscard]] PetErgResult simulate_planned(const PetErgScenario& sc,
                                            const PetErgRowObserver& on_output);

}  // namespace attiguard::sim
