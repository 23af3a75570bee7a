#pragma once
/// @file craft_defaults.hpp
/// The guidance settings derived from the spacecraft (profile "craft", the default of kind
/// `waypoint`; docs/waypoint.md, "Tuning"): what the Waypoint paper leaves open (Algorithm 1's
/// tolerances, the braking margin of [Waypoint eq. (16)], the hand-over to the RCT of [Waypoint eqs. (28)-(30)], the PID gains
/// of [Waypoint eq. (27)]) follows from the mass, the main thrust, the RCT authority, the inertia, the wheel
/// limit and the control period. The paper's own settings are profile "paper". Each formula is
/// defined here once; the scenario reader uses them for keys the file leaves out.

#include "attiguard/control/quaternion_pid.hpp"
#include "attiguard/control/rct_position_law.hpp"

namespace attiguard::guidance {

/// What the derived defaults depend on.
struct CraftLimits {
  double mass{100.0};              ///< m [kg]
  double T_max{20.0};              ///< main thrust [N]
  double f_max{0.5};               ///< one RCT's thrust [N]
  double J_max{20.0};              ///< largest principal inertia [kg·m²]
  double J_min{20.0};              ///< smallest principal inertia [kg·m²]
  lie::Mat3 J{lie::Mat3::Identity() * 20.0};  ///< inertia in the body frame [kg·m²]
  double max_wheel_torque{0.0};    ///< per-axis wheel limit, 0 = none [N·m]
  double control_period{0.1};      ///< T_s [s]
  [[nodiscard]] double a_main() const noexcept { return T_max / mass; }  ///< [m/s²]
  [[nodiscard]] double a_rct() const noexcept { return f_max / mass; }   ///< [m/s²]
};

/// Pointing tolerance on the thrust axis, sin(α/2): fire the main engine only when x_b is within
/// α = clamp(f_max/(2 T_max), 2e-3, 0.05) rad of x_d, so that the lateral acceleration of a
/// misaligned firing, α T_max/m, is at most half of what one RCT can take back.
[[nodiscard]] double craft_pointing_tolerance(const CraftLimits& c) noexcept;

/// Braking margin γ of [Waypoint eq. (16)]: one control period of firing delay at the cruise speed V_d costs
/// V_d T_s of braking distance; γ = clamp(1/(1 + 4 a T_s/V_d), 0.5, 0.95) keeps that (with a
/// factor 2) inside the margin of the braking curve.
[[nodiscard]] double craft_braking_margin(const CraftLimits& c, double cruise_speed) noexcept;

/// Main-engine cut-off speed: one control period of full thrust, a T_s (the speed quantum of the
/// on/off engine; the paper's 0.02 m/s), at most half the cruise speed [m/s].
[[nodiscard]] double craft_main_cutoff_speed(const CraftLimits& c, double cruise_speed) noexcept;

/// Speed below which the velocity projection [Waypoint eqs. (17)-(22)] fades out: 2.5 a T_s [m/s]
/// (above it, one period of thrust turns v̂ by less than ≈ 0.4 rad, so x_d = −v̂ does not spin).
/// The paper's 0.05 m/s is the paper profile's; as a floor it left a slow craft (cruise speeds of
/// centimetres per second) braking with the projection faded, pointed at a line of sight that
/// swings near the waypoint (docs/waypoint.md, "Lateral RCT").
[[nodiscard]] double craft_projection_blend_speed(const CraftLimits& c) noexcept;

/// Distance the RCT need to stop from `speed` at half their authority (the bang-bang threshold
/// of the allocation): speed²/(a_rct) [m].
[[nodiscard]] double rct_stopping_distance(const CraftLimits& c, double speed) noexcept;

/// Re-plan distance: max(25 δ_p, 10 δ, 4 × rct_stopping_distance(cut-off speed),
/// a_rct t_slew²/2) [m], so that the RCT stop what the main engine leaves well inside it, and
/// so that the legs the RCT fly faster than the main engine can flip (half of it: a_rct t_slew²/4,
/// the RCT's bang-bang distance in one slew time) are left to them.
[[nodiscard]] double craft_replan_distance(const CraftLimits& c, double cutoff_speed,
                                           double position_accuracy, double arrival_radius,
                                           double slew_time) noexcept;

/// RCT gains of [Waypoint eq. (28)]: κ_d = a_rct/δ_v (at the bang-bang threshold f_max/2 an RCT fires once
/// ‖v‖ ≥ δ_v/2), κ_p from craft_kappa_p(), then κ_d raised to κ_p/λ if needed so that the
/// switching line is never steeper than λ = craft_rct_slope().
[[nodiscard]] control::RctPositionGains craft_rct_gains(const CraftLimits& c, double speed_accuracy,
                                                         double position_accuracy) noexcept;

/// Braking curve of the RCT law far from the waypoint (RctPositionGains::braking_acceleration):
/// half the RCT authority, a_rct/2 [m/s²], so that the on/off thrusters (firing at full f_max
/// above their threshold) take out the speed of the curve √(a_rct ‖e‖) with a factor 2 to spare
/// (docs/waypoint.md, "Fine control far from the waypoint").
[[nodiscard]] double craft_rct_braking_acceleration(const CraftLimits& c) noexcept;

/// Slope λ of the RCT switching line v = λ e: min(√(a_rct/(12.5 δ_p)), 0.1/T_s) [1/s] (see
/// craft_kappa_p()).
[[nodiscard]] double craft_rct_slope(const CraftLimits& c, double position_accuracy) noexcept;
/// κ_p of craft_rct_gains() for a given κ_d [1/s²]: the on/off RCT slide along the switching line
/// κ_p e = κ_d v, v = λ e; λ = κ_p/κ_d = min(√(a_rct/(12.5 δ_p)), 0.1/T_s) is the steepest line
/// they can follow from half the default re-plan distance (λ² e ≤ a_rct) and that the sampled
/// loop resolves; κ_p = max(λ κ_d, a_rct/δ_p) (an RCT fires once ‖e‖ ≥ δ_p/2).
[[nodiscard]] double craft_kappa_p(const CraftLimits& c, double kappa_d,
                                   double position_accuracy) noexcept;

/// Dead band of the bang-bang RCT law [Waypoint eqs. (28)-(30)] at rest: no thruster fires while
/// κ_p ‖e‖ < threshold · a_rct, i.e. within threshold · a_rct/κ_p of the waypoint [m]
/// (+∞ for κ_p = 0).
[[nodiscard]] double rct_position_dead_band(const CraftLimits& c, const control::RctPositionGains& g,
                                            double threshold) noexcept;

/// Speed dead band of [Waypoint eqs. (28)-(30)] on the waypoint: threshold · a_rct/κ_d [m/s].
[[nodiscard]] double rct_speed_dead_band(const CraftLimits& c, const control::RctPositionGains& g,
                                         double threshold) noexcept;

/// Speed change of one RCT firing for one control period, a_rct T_s [m/s]: the resolution of the
/// sampled on/off thrusters.
[[nodiscard]] double rct_speed_quantum(const CraftLimits& c) noexcept;

/// Speed the main engine can leave when it cuts off: max(cut-off speed, a T_s/2) (braking stops
/// within half a period of the cut-off at best) [m/s].
[[nodiscard]] double main_speed_left(const CraftLimits& c, double cutoff_speed) noexcept;

/// Shortest half-turn slew the wheels allow, 2√(π J_max/τ_w) (bang-bang torque), 0 without a
/// limit [s].
[[nodiscard]] double wheel_half_turn_time(const CraftLimits& c) noexcept;

/// Critically damped attitude PD (27), shaped by the inertia (QuaternionPidGains::shaped,
/// S = J/J_max, with the ω × J ω feed-forward) so that every principal axis, however unequal the
/// moments, has the same natural frequency ω_n = min(0.3, 0.1/T_s) rad/s (the sampled derivative
/// term k_d S_ii T_s/(2 J_i) = 2 ω_n T_s ≤ 0.2 on every axis) and, with a wheel limit τ_w, at most
/// √(τ_w/(2 J_max)); k_p = 2 ω_n² J_max, k_d = 4 ω_n J_max (ε ≈ θ/2 in [Waypoint eq. (27)]); k_i = 0.
[[nodiscard]] control::QuaternionPidGains craft_attitude_gains(const CraftLimits& c) noexcept;

/// Estimated duration of a half-turn slew with the gains `gains` (10/ω_n of the PD (27)) or, with
/// a wheel limit, of the bang-bang slew 2√(π J_max/τ_w) if longer [s].
[[nodiscard]] double craft_slew_time(const CraftLimits& c,
                                     const control::QuaternionPidGains& gains) noexcept;

}  // namespace attiguard::guidance
