#pragma once
/// @file attitude_state.hpp
/// The rigid-body attitude state (R_ib, ω_b) ∈ SO(3) × R³ and its vector field.

#include "attiguard/dynamics/rigid_body.hpp"
#include "attiguard/integrate/product_state.hpp"

namespace attiguard::dynamics {

/// (R_ib, ω_b): R[0] is the attitude (body → inertial), x the body angular velocity [rad/s].
using AttitudeState = integrate::ProductState<1, 3>;

/// Time derivative of (R, ω) under torque τ_b as a body-velocity tangent [ω; ω̇]:
/// Ṙ = R ω̂, J ω̇ = (J ω) × ω + τ [PET-ERG eq. (1)]. Allocation-free.
[[nodiscard]] inline AttitudeState::Tangent attitude_derivative(const RigidBody& body,
                                                                const AttitudeState& y,
                                                                const Vec3& tau_b) noexcept {
  AttitudeState::Tangent d;
  d.head<3>() = y.x;
  d.tail<3>() = body.angular_acceleration(y.x, tau_b);
  return d;
}

}  // namespace attiguard::dynamics
