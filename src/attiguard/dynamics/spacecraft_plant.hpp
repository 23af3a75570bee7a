#pragma once
/// @file spacecraft_plant.hpp
/// Spacecraft with one main thruster along body x (or a misaligned axis near it), six on/off
/// reaction-control thrusters and
/// reaction wheels: translational dynamics [Waypoint eqs. (2)-(3)] and attitude dynamics [Waypoint eqs. (4)-(5)] of the waypoint
/// paper, simulated on SO(3) × R⁹ (attitude as R_ib; quaternions are outputs).

#include "attiguard/dynamics/rigid_body.hpp"
#include "attiguard/integrate/product_state.hpp"

namespace attiguard::dynamics {

/// (R_ib; ω_b, p_i, v_i): R[0] body → inertial, x = [ω_b (0..2), p_i (3..5), v_i (6..8)].
using SpacecraftState = integrate::ProductState<1, 9>;

/// ω^b_{i,b} of [Waypoint eq. (5)], p^i and v^i of [Waypoint eqs. (2)-(3)] (Waypoint paper) read from the state.
[[nodiscard]] inline Vec3 omega_b_of(const SpacecraftState& y) noexcept { return y.x.segment<3>(0); }
[[nodiscard]] inline Vec3 p_i_of(const SpacecraftState& y) noexcept { return y.x.segment<3>(3); }
[[nodiscard]] inline Vec3 v_i_of(const SpacecraftState& y) noexcept { return y.x.segment<3>(6); }

/// Actuator commands held over one control period.
struct SpacecraftInputs {
  Vec3 tau_b{Vec3::Zero()};    ///< wheel torque command [N·m]
  double thrust{0.0};          ///< main thrust T along the engine axis (x_b nominally), 0 or T_max [N]
  Vec3 f_rct_b{Vec3::Zero()};  ///< net RCT body force B T_RCT [N]
};

/// Mass, inertia, the optional per-axis wheel torque limit and the main engine's actual axis.
class SpacecraftPlant {
 public:
  /// m and J of [Waypoint eqs. (3), (5)]. `main_thrust_axis_b` is the unit direction the
  /// main engine really pushes along in the body frame: x_b in the paper; a mounting
  /// misalignment tilts it, which the guidance does not know (it points x_b) and must absorb.
  /// Throws InputError for an invalid inertia (RigidBody); mass > 0 and a unit axis are the
  /// caller's checks.
  SpacecraftPlant(double mass, const Mat3& J, double max_wheel_torque = 0.0,
                  const Vec3& main_thrust_axis_b = Vec3::UnitX())
      : body_(J), mass_(mass), max_wheel_torque_(max_wheel_torque),
        main_thrust_axis_b_(main_thrust_axis_b) {}

  [[nodiscard]] double mass() const noexcept { return mass_; }
  [[nodiscard]] const RigidBody& body() const noexcept { return body_; }

  /// The torque τ^b of [Waypoint eq. (5)] (Waypoint paper) the wheels deliver: the command clamped per axis to ±max_wheel_torque when a
  /// limit is set (the paper assumes none).
  [[nodiscard]] Vec3 applied_torque(const Vec3& tau_cmd_b) const noexcept {
    if (max_wheel_torque_ > 0.0) {
      return tau_cmd_b.cwiseMax(-max_wheel_torque_).cwiseMin(max_wheel_torque_);
    }
    return tau_cmd_b;
  }

  /// v̇^i = (1/m) R_b^i (f^b_Thruster + f^b_RCT), f^b_Thruster = T a_b ([Waypoint eq. (3)],
  /// where a_b = [1, 0, 0]; a_b = main_thrust_axis_b here).
  [[nodiscard]] Vec3 acceleration_i(const Mat3& R_ib, const SpacecraftInputs& u) const noexcept {
    return R_ib * (u.thrust * main_thrust_axis_b_ + u.f_rct_b) / mass_;
  }

  /// Body-velocity tangent [ω_b; ω̇_b; ṗ_i; v̇_i] of [Waypoint eqs. (2)-(5)]:
  /// Ṙ = R S(ω) (equivalent to [Waypoint eq. (4)]), J ω̇ = −S(ω) J ω + τ (5), ṗ = v (2), v̇ from [Waypoint eq. (3)].
  [[nodiscard]] SpacecraftState::Tangent derivative(const SpacecraftState& y,
                                                    const SpacecraftInputs& u) const noexcept {
    SpacecraftState::Tangent d;
    const Vec3 omega_b = omega_b_of(y);
    d.segment<3>(0) = omega_b;
    d.segment<3>(3) = body_.angular_acceleration(omega_b, applied_torque(u.tau_b));
    d.segment<3>(6) = v_i_of(y);
    d.segment<3>(9) = acceleration_i(y.R[0], u);
    return d;
  }

 private:
  RigidBody body_;
  double mass_;
  double max_wheel_torque_;
  Vec3 main_thrust_axis_b_;
};

}  // namespace attiguard::dynamics
