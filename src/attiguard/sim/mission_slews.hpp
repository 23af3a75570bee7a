#pragma once
/// @file mission_slews.hpp
/// The `planned` governor mode of kind `mission` (docs/mission.md, "Planned slews"): each
/// attitude slew of the waypoint guidance is planned when it starts, from the craft's attitude
/// and rate then to the guidance's desired attitude, with the planned mode's problem and
/// derivations (sim/planned_run.hpp, planned_setup; docs/pet-erg.md, section 16.2), and flown by
/// governor::PlannedGovernor; between slews the tracking law follows the guidance's R_d(t).

#include <optional>
#include <string>
#include <vector>

#include "attiguard/dynamics/spacecraft_plant.hpp"
#include "attiguard/governor/planned_governor.hpp"
#include "attiguard/guidance/waypoint_sequencer.hpp"
#include "attiguard/sim/mission_scenario.hpp"
#include "attiguard/sim/pet_erg_scenario.hpp"
#include "attiguard/sim/planned_figures.hpp"

namespace attiguard::sim {

/// φ(R_Tᵀ R) at or below which a slew has converged onto its target R_T (0.81°; the pet_erg
/// default convergence tolerance).
inline constexpr double kMissionSlewConvergence = 1e-4;

/// One attitude slew of a planned mission (docs/mission.md, "Planned slews").
struct MissionSlew {
  int index{0};
  double start_time{0.0};       ///< the control sample the slew started at [s]
  int waypoint{0};              ///< the guidance's active waypoint then
  guidance::Mode mode{guidance::Mode::align};  ///< the guidance's mode then
  double angle{0.0};            ///< d(R, R_T) at the start [rad]
  bool planned{false};          ///< false: too short to plan, tracked (not_planned_reason)
  std::string not_planned_reason;
  /// The planned mode's set-up figures (plan, gains, headroom, margin, T_s) and its clock's
  /// (samples, inadmissible_samples, brakes, min_rate, time_held, max_demand_ratio,
  /// saturated_commands; progress_end_time is relative to start_time).
  PlannedFigures figures;
  double convergence_time{-1.0};  ///< first sample with φ(R_Tᵀ R) ≤ 1e-4, after start_time [s]; −1: none
  double end_time{0.0};           ///< the next slew's start, or the end of the flight [s]
};

/// What the planned mission's loop is doing at a control sample (trajectory columns).
struct MissionSlewState {
  int slew{-1};        ///< the planned slew being flown (−1: tracking R_d between slews)
  double sigma{0.0};   ///< σ of its plan [s]
  double rate{0.0};    ///< ṡ
};

/// The planning problem of a slew of `sc` starting at (R_ib, ω_b) towards R_d, as the pet_erg
/// scenario planned_setup takes (docs/mission.md, "Planned slews"; docs/pet-erg.md, section
/// 16.2): J, [control] kp, kd, tau_max, the cones, the control period, and the per-axis wheel
/// clamp max_wheel_torque as three orthogonal wheels (the plan's torque is then their inscribed
/// radius). Set-up code: allocates.
[[nodiscard]] PetErgScenario mission_slew_scenario(const MissionScenario& sc, const lie::Mat3& R_ib,
                                                   const lie::Vec3& omega_b, const lie::Mat3& R_d);

/// The planned mission's attitude loop (docs/mission.md, "Planned slews"). A slew starts at a
/// control sample where the guidance's R_d is further than align_tolerance from where the loop
/// is heading (the current plan's target, or the R_d tracked at the previous sample): it is then
/// planned (planned_setup, which may allocate and throw the planner's VerificationFailure) and
/// flown by PlannedGovernor::step until σ = T_p; a slew whose plan would be shorter than ten
/// control periods (PlannedSetupRefusal) is tracked instead. Otherwise the tracking law with
/// ω̇_d = 0 follows R_d and the guidance's ω_d, its torque scaled onto the bound as the planned
/// mode's saturation.
class MissionSlews {
 public:
  explicit MissionSlews(const MissionScenario& sc);

  /// The command at control sample t for the measured state y and the guidance's command
  /// (docs/mission.md, "Planned slews", points 1-4): a slew's start plans it (set-up, allocates),
  /// the other samples step the planned governor or the tracking law (no allocation).
  const governor::GovernorOutput& step(double t, const dynamics::SpacecraftState& y,
                                       const guidance::MissionCommand& cmd);

  /// The loop's state at the last step (trajectory columns slew, s, s_dot; docs/mission.md,
  /// "Planned slews", "Outputs").
  [[nodiscard]] const MissionSlewState& state() const noexcept { return state_; }

  /// The slews flown, the last one ended at `end_time` (summary.json `slews`; docs/mission.md,
  /// "Planned slews", "Outputs").
  [[nodiscard]] std::vector<MissionSlew> finish(double end_time) &&;

 private:
  void start_slew(double t, const lie::Mat3& R, const lie::Vec3& omega, const lie::Mat3& R_d,
                  const guidance::MissionCommand& cmd);
  void fly_plan(double t, const lie::Mat3& R, const lie::Vec3& omega);
  void track(const lie::Mat3& R, const lie::Vec3& omega, const lie::Mat3& R_d, const lie::Vec3& omega_d);

  const MissionScenario& sc_;
  double tau_bound_{0.0};
  control::TrackingGains gains_;
  std::optional<governor::PlannedGovernor> gov_;
  bool flying_{false};
  lie::Mat3 heading_{lie::Mat3::Identity()};  ///< the plan's target, or the R_d tracked
  lie::Mat3 target_{lie::Mat3::Identity()};   ///< the last slew's target R_T
  std::vector<MissionSlew> slews_;
  governor::GovernorOutput out_;
  MissionSlewState state_;
};

}  // namespace attiguard::sim
