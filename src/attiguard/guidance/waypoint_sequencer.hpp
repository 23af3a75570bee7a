#pragma once
/// @file waypoint_sequencer.hpp
/// The waypoint sequencer: the waypoint mission as an explicit state machine — the "future work" of the Waypoint paper
/// (Conclusion) built from its Algorithm 1:
///
///   align → accelerate → coast → flip → decelerate → fine → (next waypoint: align | done)
///
/// per waypoint, with every switching rule a parameter and each transition reported (with its
/// reason) in the command of the step where it happens. The step is noexcept and
/// allocation-free: the waypoints are a non-owning span and the caller records transitions.

#include <cmath>
#include <limits>
#include <span>

#include "attiguard/control/quaternion_pid.hpp"
#include "attiguard/control/rct_allocation.hpp"
#include "attiguard/control/rct_position_law.hpp"
#include "attiguard/dynamics/spacecraft_plant.hpp"
#include "attiguard/guidance/desired_attitude.hpp"

namespace attiguard::guidance {

/// Waypoint sequencer modes (their integer values are the `mode` column of trajectory.csv).
enum class Mode : int {
  align = 0,       ///< point x_b at the waypoint, T = 0, until ‖ε_{d,b}‖ < pointing tolerance
  accelerate = 1,  ///< T from [Waypoint eq. (13)] while pointing within tolerance
  coast = 2,       ///< T = 0 after the acceleration distance (or V_d reached), attitude held on e
  flip = 3,        ///< rotate 180° onto the reversed error frame (Fig. 1(b)), T = 0
  decelerate = 4,  ///< T from [Waypoint eqs. (15)-(16)] with the velocity projection [Waypoint eqs. (17)-(24)]
  fine = 5,        ///< RCT law [Waypoint eqs. (28)-(30)], attitude held, until δ_p / δ_v are met
  done = 6,        ///< every waypoint visited; attitude held, no thrust
  /// Beyond the paper: main engine against the velocity (x_d = −v̂ held) until ‖v‖ ≤ the cut-off
  /// speed, entered when the speed left is more than the RCT can stop within half the re-plan
  /// distance (after a closest approach, or before a re-plan); then fine. See brake_speed.
  brake = 7,
  /// Beyond the paper: an RCT-only leg (a leg within half the re-plan distance) flown by the RCT
  /// near time-optimally along the line of sight, speed across it nulled (guidance/rct_transfer.hpp;
  /// docs/waypoint.md, "The RCT-only legs"), attitude held; then fine near the waypoint.
  rct_transfer = 8,
};

/// Number of modes (codes 0 … kModeCount − 1).
inline constexpr int kModeCount = 9;

/// Lower-case name of a mode ("align", …) of the Waypoint paper's Algorithm 1 as a state machine.
[[nodiscard]] const char* mode_name(Mode mode) noexcept;

/// When the coast ends and the flip starts. Both also flip when the braking point is due (the
/// predicted stopping distance, see flip_due()), so a craft already fast never coasts past it.
enum class FlipTiming {
  immediate,      ///< as the paper: as soon as the acceleration fraction of the leg is covered
  braking_point,  ///< when ‖e‖ − v_c²/(2 γ T_max/m) ≤ v_c · flip_lead_time (v_c closing speed)
};

/// Why a transition happened.
enum class TransitionReason : int {
  none = 0,
  pointing_reached,      ///< ‖ε_{d,b}‖ < pointing tolerance (align → accelerate, flip → decelerate)
  acceleration_done,     ///< ‖e‖ < (1 − fraction) ‖e(0)‖ (Algorithm 1's 0.8)
  cruise_speed_reached,  ///< ‖v‖ > V_d (13)
  flip_point,            ///< coast → flip by the flip timing rule
  arrival_sphere,        ///< ‖e‖ ≤ δ (Algorithm 1's outer loop)
  main_cutoff_speed,     ///< ‖v‖ ≤ main-engine cut-off speed while decelerating
  closest_approach,      ///< ∠(e, v) ≥ acos(c_full) (≈ 90°) while decelerating: closest approach
  accuracy_met,          ///< fine control: ‖e‖ < δ_p and ‖v‖ < δ_v (or only ‖v‖ < δ_v if κ_p = 0)
  replan,                ///< fine control: ‖e‖ > replan distance, the leg restarts with align
  speed_left,            ///< ‖v‖ > brake speed at a closest approach or a re-plan: brake first
  braked,                ///< brake: ‖v‖ ≤ main-engine cut-off speed
  /// Beyond the paper: closing speed ê·v ≤ 0 while coasting or flipping (moving away from the
  /// waypoint, or past it): re-plan (brake first when more than the brake speed is left).
  overshoot,
  /// Beyond the paper: the speed across the line of sight, ‖v − (ê·v) ê‖, exceeds
  /// max(brake speed, V_d/4) before braking: thrust along ê would not remove it, so brake to
  /// rest first and re-plan.
  lateral_speed,
  /// Beyond the paper: rct_transfer → fine at rest at the end of its braking curve with the
  /// accuracies not met (guidance::rct_transfer_handover_due).
  handover,
};

/// Lower-case name of a transition reason ("pointing_reached", …), Waypoint paper Algorithm 1.
[[nodiscard]] const char* reason_name(TransitionReason reason) noexcept;

/// Every parameter of the mission logic (Algorithm 1 and the choices the paper leaves open).
struct MissionParams {
  double mass{100.0};        ///< m [kg]
  double T_max{20.0};        ///< main thrust [N]
  double f_max{0.5};         ///< RCT thrust [N]
  double cruise_speed{100.0};         ///< V_d of [Waypoint eq. (13)] [m/s]
  double acceleration_fraction{0.2};  ///< accelerate over this fraction of the leg (Sec. VI)
  double pointing_tolerance{1e-6};    ///< fire only when the pointing error < this (Algorithm 1)
  bool pointing_thrust_axis{false};   ///< error = sin(∠(x_b, x_d)/2) (roll ignored) instead of ‖ε_{d,b}‖
  double arrival_radius{1.0};         ///< δ [m]
  double position_accuracy{0.5};      ///< δ_p [m]
  double speed_accuracy{0.01};        ///< δ_v [m/s]
  bool brake_along_velocity{true};    ///< (15) with d = e·v̂ (distance to closest approach) instead of ‖e‖
  double braking_margin{1.0};         ///< γ of deceleration_thrust(): (16) fires at γ T_max
  double main_cutoff_speed{0.02};     ///< decelerate → fine below this speed [m/s]
  double replan_distance{50.0};       ///< fine → align (restart leg) beyond this distance [m]
  /// Brake with the main engine (Mode::brake) when more speed than this is left after a closest
  /// approach or at a re-plan [m/s]; ≤ 0: never (Algorithm 1 as printed). Scenario default:
  /// √(replan_distance · f_max/m), the speed the RCT stop within half the re-plan distance.
  double brake_speed{0.0};
  bool velocity_projection{true};     ///< [Waypoint eqs. (17)-(22)] while flipping/decelerating
  /// RCT null the speed across the line of sight in align, accelerate, coast and flip while
  /// the miss distance exceeds the arrival radius (control::rct_lateral_force;
  /// beyond the paper; docs/waypoint.md, "Lateral RCT")
  bool lateral_rct{false};
  /// RCT-only legs are flown in Mode::rct_transfer (guidance/rct_transfer.hpp) instead of by
  /// fine control's law [Waypoint eq. (28)] alone (beyond the paper; docs/waypoint.md, "The
  /// RCT-only legs")
  bool rct_transfer{false};
  VelocityProjectionParams projection{};
  FlipTiming flip_timing{FlipTiming::immediate};
  double flip_lead_time{60.0};        ///< [s], FlipTiming::braking_point only
  control::RctPositionGains rct{};    ///< κ_p, κ_d of [Waypoint eq. (28)]
  double rct_threshold{0.5};          ///< bang-bang: on when T_j ≥ threshold · f_max
  double reanchor_cos{0.0};           ///< re-anchor the error-frame chart when cos ϑ < this
  double e_floor{1e-6};               ///< [m], error_frame()
};

/// The default brake speed (beyond the Waypoint paper): √(replan_distance · f_max / m), the speed
/// the RCT alone stop within half the re-plan distance.
[[nodiscard]] inline double default_brake_speed(const MissionParams& p) noexcept {
  return std::sqrt(p.replan_distance * p.f_max / p.mass);
}

/// Closing speed towards the waypoint, v_c = ê·v with ê = e/‖e‖ (0 when e = 0) [m/s]: the speed
/// the guidance's decisions use (docs/waypoint.md, "State machine"), not ‖v‖.
[[nodiscard]] inline double closing_speed(const Vec3& e_i, const Vec3& v_i) noexcept {
  const double d = e_i.norm();
  return d > 0.0 ? e_i.dot(v_i) / d : 0.0;
}

/// Miss distance of the straight line the craft flies, ‖v_⊥‖ ‖e‖/‖v‖ = ‖e‖ sin ∠(e, v) with v_⊥
/// the velocity across the line of sight, while closing (ê·v > 0): the distance at the closest
/// approach; +∞ when not closing, 0 at e = 0 [m] (docs/waypoint.md, "Lateral RCT").
[[nodiscard]] inline double miss_distance(const Vec3& e_i, const Vec3& v_i) noexcept {
  const double d = e_i.norm();
  if (!(d > 0.0)) return 0.0;
  const double closing = e_i.dot(v_i) / d;
  if (!(closing > 0.0)) return std::numeric_limits<double>::infinity();
  return (v_i - e_i * (closing / d)).norm() * d / v_i.norm();
}

/// Predicted stopping distance at the closing speed v_c with the braking margin γ of [Waypoint eq. (16)]:
/// v_c²/(2 γ T_max/m) for v_c > 0, else 0 [m] ([Waypoint eq. (14)] with final speed 0).
[[nodiscard]] inline double stopping_distance(double closing, const MissionParams& p) noexcept {
  return closing > 0.0 ? closing * closing / (2.0 * p.braking_margin * p.T_max / p.mass) : 0.0;
}

/// Measured state at a control sample.
struct MissionInputs {
  lie::Mat3 R_ib{lie::Mat3::Identity()};
  Vec3 omega_b{Vec3::Zero()};
  Vec3 p_i{Vec3::Zero()};
  Vec3 v_i{Vec3::Zero()};
  double dt{0.1};  ///< time to the next sample [s]
};

/// Commands and diagnostics of one sample.
struct MissionCommand {
  dynamics::SpacecraftInputs inputs{};  ///< τ_b, T, f_RCT^b held until the next sample
  control::RctVector rct{control::RctVector::Zero()};  ///< the six thruster forces [N]
  Mode mode{Mode::align};
  int waypoint{0};  ///< index of the active waypoint (= count when done)
  bool transition{false};
  Mode from{Mode::align};
  TransitionReason reason{TransitionReason::none};
  Quat q_id{Quat(1.0, 0.0, 0.0, 0.0)};  ///< desired attitude [Waypoint eq. (23)]
  Vec3 omega_d_d{Vec3::Zero()};         ///< feed-forward (24)
  double pointing_error{0.0};           ///< ‖ε_{d,b}‖, or sin(∠(x_b, x_d)/2) (thrust axis)
  double projection_weight{0.0};        ///< λ of velocity_frame()
  Quat q_ib{Quat(1.0, 0.0, 0.0, 0.0)};  ///< measured attitude, sign kept continuous in time
  GuidanceFrameSpec spec{};  ///< frame of this sample (chart, sign, projection) for checks
};

/// The waypoint state machine (Waypoint paper, Algorithm 1; docs/waypoint.md, "State machine")
/// with its attitude PID; formerly guidance::Mission (not the kind `mission`, sim/mission_run).
/// Not copyable across waypoint storage: the waypoint span must outlive the sequencer.
class WaypointSequencer {
 public:
  /// Sequencer over `waypoints_i` (the array P_wp of the Waypoint paper, Sec. VI) with the PID
  /// gains of [Waypoint eq. (27)]; the first leg starts at the first step().
  WaypointSequencer(const MissionParams& params, const control::QuaternionPidGains& gains,
                    std::span<const Vec3> waypoints_i) noexcept;

  /// One control sample (Algorithm 1 body): transitions, desired attitude [Waypoint eqs. (23)-(24)], thrust
  /// (13)/(16), RCT [Waypoint eqs. (28)-(30)], PID [Waypoint eq. (27)]. Noexcept, allocation-free.
  [[nodiscard]] MissionCommand step(const MissionInputs& in) noexcept;

  [[nodiscard]] Mode mode() const noexcept { return mode_; }
  [[nodiscard]] int waypoint() const noexcept { return index_; }
  [[nodiscard]] bool done() const noexcept { return mode_ == Mode::done; }
  /// The guidance frame of the current mode (chart, sign of e in [Waypoint eq. (6)], projection (17)), for tests.
  [[nodiscard]] GuidanceFrameSpec frame_spec() const noexcept;
  [[nodiscard]] const MissionParams& params() const noexcept { return params_; }

 private:
  void start_leg(const MissionInputs& in) noexcept;
  [[nodiscard]] Quat continuous_q_ib(const lie::Mat3& R_ib) const noexcept;
  [[nodiscard]] TransitionReason state_transition(const MissionInputs& in, Mode& next) const noexcept;
  void enter(Mode next, const MissionInputs& in) noexcept;
  /// The measured attitude with its sign kept continuous; the first leg starts at the first sample.
  void begin_sample(const MissionInputs& in) noexcept;
  /// Step (a) of step(): the transition decided by position and velocity (state_transition),
  /// entered; accuracy_met moves on to the next waypoint (or done).
  void take_position_transition(const MissionInputs& in, MissionCommand& cmd) noexcept;
  /// Step (c) of step(): align → accelerate and flip → decelerate once pointed (within the
  /// pointing tolerance), unless a transition was already taken this sample.
  void take_pointing_transition(double pointing, MissionCommand& cmd) noexcept;
  /// More speed than the RCT can take back: brake with the main engine first (Mode::brake).
  [[nodiscard]] bool brake_needed(double speed) const noexcept {
    return params_.brake_speed > 0.0 && speed > params_.brake_speed;
  }
  [[nodiscard]] DesiredAttitude evaluate(const MissionInputs& in, const Vec3& a_i) noexcept;

  MissionParams params_;
  control::QuaternionPid pid_;
  std::span<const Vec3> waypoints_;
  int index_{0};
  Mode mode_{Mode::align};
  bool started_{false};
  double leg_distance_{0.0};  ///< ‖e(0)‖ of the leg
  Quat chart_accel_{Quat(1.0, 0.0, 0.0, 0.0)};
  Quat chart_decel_{Quat(1.0, 0.0, 0.0, 0.0)};
  Quat q_hold_{Quat(1.0, 0.0, 0.0, 0.0)};
  Quat q_last_{Quat(1.0, 0.0, 0.0, 0.0)};  ///< last desired attitude
  Quat q_ib_{Quat(1.0, 0.0, 0.0, 0.0)};    ///< last measured attitude (continuous sign)
};

}  // namespace attiguard::guidance
