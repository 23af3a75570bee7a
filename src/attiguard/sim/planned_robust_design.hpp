#pragma once
/// @file planned_robust_design.hpp
/// The robust margins of a planned run (docs/pet-erg.md, section 16.3): the robust margin of the
/// tracking loop on a given plan (governor/robust_tracking_margin.hpp) and what it asks of the
/// plan, the cone margin θ(L) + β and the torque bound of the level set plus the command error.
/// Set-up code (allocates, throws SetupError).

#include "attiguard/control/so3_tracking.hpp"
#include "attiguard/governor/planned_governor.hpp"
#include "attiguard/governor/progress_governor.hpp"
#include "attiguard/governor/robust_tracking_margin.hpp"
#include "attiguard/governor/slew_plan.hpp"
#include "attiguard/governor/torque_slabs.hpp"
#include "attiguard/sim/pet_erg_scenario.hpp"

namespace attiguard::sim {

/// The robust margin of one plan and what it needs (docs/pet-erg.md, section 16.3, "Design").
struct PlannedRobustDesign {
  governor::RobustTrackingMargin margin;  ///< the flight, from the gate at the clock rate ṡ
  governor::RobustTrackingMargin rest;    ///< the wait at σ = 0, from the scenario's start
  double gate_attitude{0.0};        ///< the clock starts when the measured ‖e_R‖ is within this
  double gate_rate{0.0};            ///< … and the measured ‖e_Ω‖ within this [rad/s]
  governor::PlannedRobust params;   ///< what PlannedGovernor flies with
  double cone_margin_needed{0.0};   ///< θ(L/(1 − δ)) + β [rad]
  double plan_cone_margin{0.0};     ///< the plan's smallest cone margin between its samples [rad] (+∞: no cone)
  double torque_needed{0.0};        ///< the law's bound over the level set plus the command error [N·m]
  double torque_limit{0.0};         ///< what the command must stay within [N·m]
  double rate{1.0};                 ///< the clock's rate ṡ the plan is flown at
  /// With wheels: the command's largest gauge against their slabs within τ_max (≤ 1 keeps it);
  /// 0 without wheels (docs/pet-erg.md, section 16.3, "Wheels")
  double torque_ratio{0.0};
  bool wheel_slabs{false};          ///< the torque is judged by torque_ratio (wheels), else by the ball
  /// The command stays within what the actuators apply unclipped.
  [[nodiscard]] bool torque_holds() const noexcept {
    return wheel_slabs ? torque_ratio <= 1.0 : torque_needed <= torque_limit;
  }
  /// Both hold: the plan keeps every cone by θ + β and the command stays within its limit.
  [[nodiscard]] bool holds() const noexcept { return plan_cone_margin >= cone_margin_needed && torque_holds(); }
};

/// max ‖dω̇_p/dt‖ over the plan [rad/s³], ω̇_p = J⁻¹(τ_p − ω_p × Jω_p) (docs/pet-erg.md, section
/// 16.3): the torque is linear between a node, the midpoint and the next node (its rate exact per
/// half-interval); the ω cubic's rate is at most max(‖ω̇_k‖, ‖ω̇_{k+1}‖) + 1.5‖D − ½(ω̇_k + ω̇_{k+1})‖,
/// D the interval's mean rate of change (the Hermite derivative's convex part plus 6s(1 − s) ≤ 1.5
/// of its bubble).
[[nodiscard]] double plan_feedforward_rate(const governor::SlewPlan& plan, double omega_max);

/// What the robust design computes once per pair of gains (docs/pet-erg.md, section 16.3): the
/// L1 norms, the wait at σ = 0 from the scenario's start and the gate that ends it.
struct PlannedRobustBasis {
  governor::PlanWindow window;             ///< the plan's extremes (at ṡ = 1)
  governor::RobustTrackingInputs flight;   ///< the flight's inputs at ṡ = 1, from the gate
  governor::TrackingGainsL1 l1;
  governor::RobustTrackingMargin rest;
  double gate_attitude{0.0};
  double gate_rate{0.0};
  /// The wheels' slabs within the declared τ_max (count 0 without wheels: the ball of the
  /// progress governor's τ_max judges the torque)
  governor::TorqueSlabs slabs{};
};

/// The wait's margin and gate for the gains of `progress` (docs/pet-erg.md, section 16.3,
/// "The wait"). Throws SetupError as compute_robust_tracking_margin.
[[nodiscard]] PlannedRobustBasis planned_robust_basis(const PetErgScenario& sc,
                                                      const governor::ProgressGovernor& progress);

/// The robust margin of flying the plan of `progress` at ṡ = `rate` from the basis of its gains.
[[nodiscard]] PlannedRobustDesign planned_robust_design(const PetErgScenario& sc,
                                                        const governor::ProgressGovernor& progress,
                                                        const PlannedRobustBasis& basis, double rate);

/// The robust margin of flying the plan of `progress` (its gains, its torque limit τ_lim of the
/// command) at the constant clock rate ṡ = `rate` in the flight loop of `sc` (docs/pet-erg.md,
/// section 16.3, "Design"). Throws SetupError as compute_robust_tracking_margin.
[[nodiscard]] PlannedRobustDesign planned_robust_design(const PetErgScenario& sc,
                                                        const governor::ProgressGovernor& progress, double rate);

}  // namespace attiguard::sim
