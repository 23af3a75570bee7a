#pragma once
/// @file robust_margin.hpp
/// Robust dynamic safety margins of the PET-ERG flight loop (docs/pet-erg.md, section 13).
///
/// Every imperfection of the flight loop (zero-order hold, one period of delay, sensor bias and
/// noise, torque quantisation, disturbance torque) is reduced to a bounded torque error
/// ‖w‖ ≤ w̄ on the plant J ω̇ = (Jω + A h) × ω + k_p s − k_d ω + w, s = sk(RᵀR_g)^∨. The governor
/// then compares the strict Lyapunov function W = V − ε ωᵀJ s (V of the PET-ERG paper, Sec.
/// III-A) with Γ_W(R_g) = (1 − δ) Γ'(R_g), Γ' the aggregate threshold computed with the torque
/// limits reduced by the command error. On the set where the bounds hold,
///   (1 − δ) V ≤ W ≤ (1 + δ) V   and   Ẇ ≤ −a‖ω‖² − b‖s‖² + c‖s‖‖ω‖ + w̄ (‖ω‖ + ε‖s‖),
/// written for the attitude R B seen through the constant attitude bias B (the cones are
/// tightened by its angle),
/// so every sublevel set {W ≤ L} with L > Γ_min is invariant under any torque error within w̄,
/// and inside it V ≤ Γ' keeps every constraint. Everything here is computed once, offline.

#include "attiguard/lie/so3.hpp"

namespace attiguard::governor {

/// The bounds the robust margin is computed from (docs/pet-erg.md, section 13, "Assumptions").
struct RobustMarginInputs {
  double kp{1.0};                 ///< k_p of [PET-ERG eq. (3)] [N·m]
  double kd{1.0};                 ///< k_d of [PET-ERG eq. (3)] [N·m·s]
  lie::Mat3 J{lie::Mat3::Identity()};  ///< inertia [kg·m²]
  double control_period{0.1};     ///< h [s], > 0
  int delay_periods{0};           ///< d ∈ {0, 1}: the torque computed at t_k is applied from t_{k+d}
  /// β ≥ ‖b_R‖, the constant attitude bias [rad]: handled geometrically (the analysis runs in the
  /// measured frame R B, the cones are tightened by β), not as a torque error
  double attitude_bias{0.0};
  double attitude_noise{0.0};     ///< σ_n ≥ the attitude noise angle [rad]
  double rate_error{0.0};         ///< σ_ω ≥ ‖ω̃ − ω‖ [rad/s]
  double quantisation_error{0.0}; ///< ≥ ‖Q(τ) − τ‖ of the command quantiser [N·m]
  double disturbance{0.0};        ///< d̄ ≥ ‖d(t)‖ [N·m]
  double applied_torque_max{1.0}; ///< ≥ ‖applied body torque‖ [N·m] (bounds ‖ω̇‖)
  double wheel_momentum_max{0.0}; ///< ≥ ‖A h‖ of the wheels [N·m·s] (assumes |h_i| ≤ h_max,i)
  double gamma_top{1.0};          ///< max over R_g of Γ' (the reduced Γ_d, capped): bounds ‖ω‖, ‖s‖
  double epsilon_gamma{0.1};      ///< ε_Γ of the cap k_p(2 − ε_Γ) ≥ Γ'
  /// Cap on one move of R_g [rad] when delay_periods = 1 (its lag enters w̄ as k_p·Δ_max);
  /// ≤ 0: derived, the lag then adds a quarter of the other errors to w̄.
  double max_reference_step{0.0};
};

/// The robust margin (docs/pet-erg.md, section 13).
struct RobustMargin {
  double epsilon{0.0};          ///< ε of the cross term of W = V − ε ωᵀJ s
  double delta{0.0};            ///< δ = ε√(λ_max/k_p): |W − V| ≤ δ V
  double omega_max{0.0};        ///< ‖ω‖ bound on {V ≤ Γ_top} [rad/s]
  double s_max{0.0};            ///< ‖s‖ bound on {V ≤ Γ_top}
  double a{0.0}, b{0.0}, c{0.0};  ///< Ẇ ≤ −a‖ω‖² − b‖s‖² + c‖s‖‖ω‖ + w̄(‖ω‖ + ε‖s‖)
  // the torque-error budget [N·m]
  double sensor_error{0.0};        ///< k_p σ_n + k_d σ_ω (the attitude bias is not in it)
  double quantisation_error{0.0};  ///< ‖Q(τ) − τ‖
  double command_error{0.0};       ///< sensor + quantisation: the torque limits are reduced by it
  double hold_error{0.0};          ///< (1 + d) h · L_τ, the staleness of the held torque
  double reference_lag_error{0.0}; ///< d · k_p · Δ_max, the delayed command's older R_g
  double disturbance{0.0};         ///< d̄
  double torque_error{0.0};        ///< w̄, the sum of the five above
  double gamma_min{0.0};           ///< Γ_min: {W ≤ L} is invariant for every L > Γ_min
  double measurement_margin{0.0};  ///< e_W ≥ |W(R̃, ω̃) − W(R, ω)| on {V ≤ Γ_top}
  double max_reference_step{0.0};  ///< Δ_max [rad] (+∞ without delay)
  double start_allowance{0.0};     ///< growth bound of W over the first d periods (zero torque)
};

/// e_cmd = k_p σ_n + k_d σ_ω + ‖Q(τ) − τ‖ ≥ ‖τ_cmd − τ_PD(R B, ω)‖, B the attitude bias: the
/// sensor-noise and quantisation part of the torque error, by which the torque limits are
/// reduced (docs/pet-erg.md, section 13, "Error budget").
[[nodiscard]] double command_error_bound(const RobustMarginInputs& in) noexcept;

/// Computes the robust margin: the error budget w̄, ε chosen on a grid to minimise
/// Γ_min/(1 − δ), and Γ_min as a certified upper bound of sup{W : Ẇ may be ≥ 0}
/// (docs/pet-erg.md, section 13). Throws SetupError with the numbers when an input is invalid
/// or no ε gives a strict Lyapunov function (set-up code only).
[[nodiscard]] RobustMargin compute_robust_margin(const RobustMarginInputs& in);

/// sup{U(x, y) : x, y ≥ 0, a y² + b x² − c x y ≤ y + ε x} with U = u_yy y² + u_xx x² + u_xy x y,
/// all coefficients ≥ 0, 4ab > c²: an upper bound within 1e-6 (relative) of the supremum
/// (interval evaluation over angle cells, branch and bound, rounding allowance 1e-9 relative),
/// the Γ_min of docs/pet-erg.md section 13 for w̄ = 1. Returns +∞ when 4ab ≤ c² (the region is
/// unbounded). Set-up code (allocates).
[[nodiscard]] double ultimate_level_bound(double a, double b, double c, double epsilon,
                                          double u_yy, double u_xx, double u_xy);

/// W = V − ε ωᵀJ sk(RᵀR_g)^∨, the strict Lyapunov function of docs/pet-erg.md section 13
/// (V of the PET-ERG paper, Sec. III-A). Allocation-free.
[[nodiscard]] double strict_lyapunov(const lie::Mat3& J, const lie::Mat3& R_ib, const lie::Vec3& omega_b,
                                     const lie::Mat3& R_g, double kp, double epsilon) noexcept;

}  // namespace attiguard::governor
