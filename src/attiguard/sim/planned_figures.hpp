#pragma once
/// @file planned_figures.hpp
/// What a `governor = "planned"` run was set up with and what its progress did
/// (docs/pet-erg.md, section 16.2): the plan's report, the tracking gains and margins and
/// whether they were derived from the craft, and the clock's figures. summary.json's `planned`
/// object (docs/scenario-format.md, "pet_erg").

#include "attiguard/control/so3_tracking.hpp"
#include <limits>
#include <optional>

#include "attiguard/plan/slew_planner.hpp"
#include "attiguard/sim/planned_robust_design.hpp"

namespace attiguard::sim {

/// The planned mode's set-up and progress figures (docs/pet-erg.md, section 16.2).
struct PlannedFigures {
  plan::PlanReport plan;           ///< the planner's report (duration, ratio, dense check)
  control::TrackingGains gains;    ///< k_R, k_Ω of the tracking law
  bool gains_derived{false};       ///< from the craft and the slew ([control] kp, kd left out)
  double natural_frequency{0.0};   ///< ω_n of the derived gains [rad/s] (0 when given)
  bool limited_by_loop_period{false};  ///< the loop-period caps lowered ω_n
  bool limited_by_sensors{false};      ///< the sensors' errors lowered ω_n
  bool limited_by_initial_rate{false}; ///< the initial rate lowered ω_n
  double cone_margin{0.0};         ///< the plan's cone margin [rad]
  bool cone_margin_derived{false};
  double torque_headroom{0.0};     ///< the plan's torque headroom (fraction of its torque limit)
  bool torque_headroom_derived{false};
  double plan_torque_limit{0.0};   ///< the torque the plan was made for [N·m]
  double tau_max{0.0};             ///< the bound the governor keeps ‖τ‖ within [N·m]
  double sample_period{0.0};       ///< T_s of the rate choice [s]
  double epsilon{0.0};             ///< ε of the thresholds
  long samples{0};                 ///< rate choices
  long inadmissible_samples{0};    ///< choices where no rate met the thresholds
  long brakes{0};                  ///< choices that braked the clock (none admissible)
  double min_rate{1.0};            ///< smallest ṡ chosen before σ reached T_p
  double time_held{0.0};           ///< time with ṡ = 0 before σ reached T_p [s]
  double progress_end_time{-1.0};  ///< first time σ = T_p (−1: never) [s]
  double final_progress{0.0};      ///< σ at the end [s]
  double final_rate{0.0};          ///< ṡ at the end
  double max_torque_bound_ratio{0.0};  ///< max over the choices of the bound / τ_max
  double max_demand_ratio{0.0};    ///< max ‖τ_law‖/τ_max the law asked for (> 1: saturated)
  long saturated_commands{0};      ///< control instants (flight loop) or observed instants
                                   ///< (continuous loop) at which the saturation acted
  double last_V{0.0};              ///< V⁺ of the last choice
  double last_gamma_g{0.0};        ///< Γ_g of the last choice
  double last_torque_bound{0.0};   ///< the torque bound of the last choice [N·m]
  /// With robust margins (docs/pet-erg.md, section 16.3): the design the plan was made for
  std::optional<PlannedRobustDesign> robust;
  /// With robust margins: max over the observed instants of W − L of the true state seen through
  /// its bias (≤ 0 by the guarantee)
  double max_W_minus_level{-std::numeric_limits<double>::infinity()};
};

}  // namespace attiguard::sim
