#pragma once
/// @file quaternion_pid.hpp
/// The quaternion PID attitude law of [Waypoint eqs. (25)-(27)], sampled.

#include "attiguard/lie/quaternion.hpp"

namespace attiguard::control {

/// Gains of [Waypoint eq. (27)].
struct QuaternionPidGains {
  double kp{20.0};  ///< proportional gain [N·m]
  double ki{2.0};   ///< integral gain [N·m/s]
  double kd{20.0};  ///< derivative gain [N·m·s]
  /// Conditional integration (anti-windup, not in the paper): ∫ε grows only while
  /// ‖ε‖ < integral_zone; 0 = always (the paper). Keeps a 180° flip from winding up the integral.
  double integral_zone{0.0};
  /// Inertia shaping (not in the paper; docs/waypoint.md, "Tuning"): when true the torque of
  /// (27) is S (−k_p ε − k_i ∫ε − k_d ε̇) with S = `shaping` (profile "craft": J/J_max, so every
  /// principal axis gets the bandwidth the scalar gains give the largest one, and the ω × J ω
  /// feed-forward `gyroscopic` J_max S is added). False = the paper's scalar law, unchanged.
  bool shaped{false};
  lie::Mat3 shaping{lie::Mat3::Identity()};  ///< S, symmetric positive definite [-]
  double shaping_scale{0.0};                 ///< J_max of S = J/J_max, for ω × J ω [kg·m²]
};

/// Output of one controller sample.
struct QuaternionPidOutput {
  lie::Vec3 tau_b{lie::Vec3::Zero()};   ///< commanded torque [N·m] (the plant applies any wheel limit)
  lie::Quat q_db{lie::Quat(1.0, 0.0, 0.0, 0.0)};  ///< attitude error q_{d,b}, [Waypoint eq. (25)]
  lie::Vec3 omega_db_b{lie::Vec3::Zero()};  ///< ω^b_{d,b} = ω^b_{i,b} − R_d^b ω^d_{i,d} (26)
  lie::Vec3 eps_dot{lie::Vec3::Zero()};     ///< ε̇_{d,b} from the kinematics [Waypoint eq. (26)]
};

/// Sampled PID [Waypoint eq. (27)]: τ^b = −k_p ε − k_i ∫ε − k_d ε̇ with ε = vec(q_{d,b}),
/// q_{d,b} = q_{d,i} ⊗ q_{i,b} ([Waypoint eq. (25)]; erratum, docs/errata.md, Waypoint 8: the paper prints q_{d,i} ⊗ q_{i,d} = 1) and
/// ε̇ = ½ (η I + S(ε)) ω^b_{d,b} from [Waypoint eq. (26)]. The integral is a forward-Euler sum over the sample
/// period (gated by integral_zone). With QuaternionPidGains::shaped the torque is
/// S(−k_p ε − k_i ∫ε − k_d ε̇) + ω × (J_max S) ω (docs/waypoint.md, "Tuning", inertia shaping).
/// Noexcept and allocation-free.
class QuaternionPid {
 public:
  explicit QuaternionPid(const QuaternionPidGains& gains) noexcept : gains_(gains) {}

  /// One sample: q_ib, omega_b the measured attitude and rate; q_id, omega_d_d the guidance
  /// output [Waypoint eqs. (23)-(24)]; dt the time until the next sample (integral update).
  [[nodiscard]] QuaternionPidOutput step(const lie::Quat& q_ib, const lie::Vec3& omega_b,
                                         const lie::Quat& q_id, const lie::Vec3& omega_d_d,
                                         double dt) noexcept;

  /// Clears the integral ∫ε of [Waypoint eq. (27)].
  void reset() noexcept { integral_.setZero(); }
  [[nodiscard]] const lie::Vec3& integral() const noexcept { return integral_; }
  [[nodiscard]] const QuaternionPidGains& gains() const noexcept { return gains_; }

 private:
  QuaternionPidGains gains_;
  lie::Vec3 integral_{lie::Vec3::Zero()};
};

/// Attitude error q_{d,b} = q_{d,i} ⊗ q_{i,b} ([Waypoint eq. (25)] corrected).
[[nodiscard]] inline lie::Quat attitude_error(const lie::Quat& q_id, const lie::Quat& q_ib) noexcept {
  return lie::quat_multiply(lie::quat_conjugate(q_id), q_ib);
}

}  // namespace attiguard::control
