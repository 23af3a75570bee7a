#pragma once
/// @file robust_tracking_margin.hpp
/// Robust margins of the planned mode (docs/pet-erg.md, section 16.3). Under the tracking law of
/// section 16 the tracking errors obey exactly
///   J ė_Ω = −k_R e_R − k_Ω e_Ω + w,   ė_R = e_Ω + v,
/// with w the torque error (every imperfection of the flight loop: zero-order hold, one period
/// of delay and its prediction, sensor noise, quantisation, disturbance, the wheels' momentum
/// change) and v = (C(R_e) − I) e_Ω + C(R_e)(Bᵀ − I) ω the attitude kinematics' departure from
/// the linear one (‖C − I‖ = sin(θ/2) for θ ≤ 60°; B the constant attitude bias, the analysis
/// running in the frame R B). In the eigenbasis of J this is three decoupled second-order linear
/// systems, so the peaks of ‖e_R‖, ‖e_Ω‖ and of the feedback torque ‖k_R e_R + k_Ω e_Ω‖ are at
/// most the initial state's free response plus the L1 norms of the impulse responses times the
/// bounds on ‖w‖ and ‖v‖. Those bounds depend on the peaks themselves (the hold's staleness
/// grows with the errors, v with θ): a small-gain fixed point closes the loop. Set-up code only
/// (allocates, throws SetupError).

#include "attiguard/control/so3_tracking.hpp"
#include "attiguard/lie/so3.hpp"

namespace attiguard::governor {

/// What the robust margin of the planned mode is computed from (docs/pet-erg.md, section 16.3,
/// "Assumptions"): the loop, the imperfections' bounds and the reference's extremes.
struct RobustTrackingInputs {
  control::TrackingGains gains;          ///< k_R [N·m], k_Ω [N·m·s]
  lie::Mat3 J{lie::Mat3::Identity()};    ///< inertia [kg·m²]
  double control_period{0.1};            ///< h [s], > 0
  int delay_periods{0};                  ///< d ∈ {0, 1} (1: the torque is predicted one period ahead)
  double attitude_bias{0.0};             ///< β ≥ ‖b_R‖ [rad] (geometric: the analysis frame R B)
  double attitude_noise{0.0};            ///< σ_n [rad]
  double rate_error{0.0};                ///< σ_ω ≥ ‖ω̃ − ω‖ [rad/s]
  double quantisation_error{0.0};        ///< ‖Q(τ) − τ‖ [N·m]
  double disturbance{0.0};               ///< d̄ [N·m]
  double wheel_momentum_max{0.0};        ///< ≥ ‖A h‖ [N·m·s]; 0: no wheels (the torque is external)
  double applied_torque_max{1.0};        ///< ≥ ‖applied torque‖ [N·m] (the saturation's bound)
  /// ≥ ‖J ω + A h‖, the total angular momentum over the horizon the guarantee is asked for
  /// (‖H(0)‖ + d̄ T) [N·m·s]; 0: λ_max‖ω‖ + H is used
  double total_momentum_max{0.0};
  double reference_rate_max{0.0};        ///< max ‖ω_d‖ of the flown reference [rad/s]
  double reference_accel_max{0.0};       ///< max ‖ω̇_d‖ [rad/s²]
  double reference_jerk_max{0.0};        ///< max ‖ω̈_d‖ [rad/s³] (the feedforward's change)
  double reference_end_accel{0.0};       ///< ‖ω̇_d‖ just before the plan ends (dropped to 0) [rad/s²]
  double initial_attitude_error{0.0};    ///< θ(0) of the analysis frame against the plan's start [rad]
  double initial_rate_error{0.0};        ///< ‖e_Ω(0)‖ = ‖ω(0)‖ (the plan starts at rest) [rad/s]
  /// The law's torque acts from t = 0 (the loop already runs, as when the clock starts after the
  /// wait); false: the first delay_periods periods have no torque (a run's start)
  bool torque_from_start{false};
};

/// The L1 norms of the error dynamics' impulse responses (docs/pet-erg.md, section 16.3): with
/// H(τ) the 3×3 response in the eigenbasis of J, ∫ max_i |h_i(τ)| dτ from the torque error w and
/// the kinematic term v to e_R, e_Ω and the feedback torque u = k_R e_R + k_Ω e_Ω.
struct TrackingGainsL1 {
  double e_R_w{0.0}, e_Omega_w{0.0}, u_w{0.0};
  double e_R_v{0.0}, e_Omega_v{0.0}, u_v{0.0};
  /// max_τ ‖H(τ)‖ from w: the peak response to a unit impulse (a short pulse of length T and
  /// size P moves the outputs by at most T P times these)
  double e_R_w_peak{0.0}, e_Omega_w_peak{0.0}, u_w_peak{0.0};
  /// Peaks of the free response (no input) from a unit initial ‖e_R‖ (…_from_e) or a unit
  /// initial ‖e_Ω‖ (…_from_z): max over τ and the modes
  double e_R_from_e{0.0}, e_R_from_z{0.0}, e_Omega_from_e{0.0}, e_Omega_from_z{0.0}, u_from_e{0.0},
      u_from_z{0.0};
};

/// The robust margin of the planned mode (docs/pet-erg.md, section 16.3).
struct RobustTrackingMargin {
  TrackingGainsL1 l1;
  // the torque-error budget at the fixed point [N·m]
  double disturbance{0.0};        ///< d̄
  double quantisation_error{0.0}; ///< ‖Q(τ) − τ‖
  double state_error{0.0};        ///< L_R Δθ + L_ω Δω: the measured (and predicted) state's error
  double hold_error{0.0};         ///< the held torque against the law's along the hold
  double wheel_error{0.0};        ///< the wheels' momentum change over the command's age
  double bias_error{0.0};         ///< λ_max 2 sin(β/2) ‖ω‖ ‖ω_d‖: the bias frame's rate mismatch
  double torque_error{0.0};       ///< ‖w‖ ≤ this, the sum of the six above
  double command_error{0.0};      ///< state + quantisation: ‖τ_cmd − τ_law(R B, ω)‖ ≤ it
  double kinematic_error{0.0};    ///< ‖v‖ ≤ this [rad/s]
  double start_error{0.0};        ///< the peak added by the first d periods' zero torque (e_R)
  double end_error{0.0};          ///< the peak added by the feedforward's drop at the plan's end (e_R)
  double attitude_error_max{0.0}; ///< θ*: the largest attitude error angle of the flight [rad]
  double e_R_max{0.0};            ///< sin θ* ≥ ‖e_R‖
  double rate_error_max{0.0};     ///< ‖e_Ω‖ ≤ this [rad/s]
  double feedback_torque_max{0.0};///< ‖k_R e_R + k_Ω e_Ω‖ ≤ this [N·m]
  int iterations{0};              ///< of the fixed point
};

/// The L1 norms of the impulse responses of J ë + k_Ω ė + k_R e = w (and of ė = z + v) over
/// 40 time constants of the slowest mode, each cell bounded above by its start value plus the
/// cell's length times a bound on the derivative (docs/pet-erg.md, section 16.3).
[[nodiscard]] TrackingGainsL1 tracking_l1_gains(const lie::Mat3& J, const control::TrackingGains& gains);

/// Computes the robust margin of the planned mode (docs/pet-erg.md, section 16.3): the peaks of
/// the errors and of the feedback torque as the least fixed point of the bounds, checked to be
/// a strict super-solution (so the errors can never reach it). Throws SetupError with the
/// numbers when the loop's gain is not below one or the fixed point lies beyond 60°.
[[nodiscard]] RobustTrackingMargin compute_robust_tracking_margin(const RobustTrackingInputs& in);
/// compute_robust_tracking_margin with the L1 norms of tracking_l1_gains(in.J, in.gains) given.
[[nodiscard]] RobustTrackingMargin compute_robust_tracking_margin(const RobustTrackingInputs& in,
                                                                  const TrackingGainsL1& l1);

}  // namespace attiguard::governor
