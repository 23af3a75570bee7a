#pragma once
/// @file frame_rate.hpp
/// Angular velocity of a frame given by an unnormalised quaternion n(t) ≠ 0.
///
/// The guidance frames of the Waypoint paper ([Waypoint eqs. (8)-(12), (18)]-(22)) are built here as
/// unnormalised quaternions whose scalar part stays bounded away from zero, so that the unit
/// quaternion q = n/‖n‖ and its rate are smooth and finite. With q̇ = ½ q ⊗ [0, ω]
/// [Waypoint eq. (4)], ω = 2 vec(q* ⊗ q̇) = 2 vec(n* ⊗ ṅ)/‖n‖²: the term of q̇ along n contributes
/// only to the scalar part. Allocation-free.

#include "attiguard/lie/quaternion.hpp"

namespace attiguard::guidance {

using lie::Mat3;
using lie::Quat;
using lie::Vec3;

/// Body-frame angular velocity of q = n/‖n‖ from n and ṅ ([Waypoint eq. (4)] solved for
/// ω): ω = 2 vec(n* ⊗ ṅ)/‖n‖². Requires n ≠ 0.
[[nodiscard]] inline Vec3 angular_velocity_of_unnormalised(const Quat& n, const Quat& n_dot) noexcept {
  const Quat p = lie::quat_multiply(lie::quat_conjugate(n), n_dot);
  return 2.0 * p.tail<3>() / n.squaredNorm();
}

/// The C¹ smoothstep S(x) = 3x² − 2x³ on [0, 1], 0 below, 1 above, and its derivative: the
/// weight that fades the velocity projection [Waypoint eqs. (17)-(22)] in and out.
struct Smoothstep {
  double value;
  double slope;
};
[[nodiscard]] inline Smoothstep smoothstep(double x) noexcept {
  if (!(x > 0.0)) {
    return {0.0, 0.0};
  }
  if (x >= 1.0) {
    return {1.0, 0.0};
  }
  return {x * x * (3.0 - 2.0 * x), 6.0 * x * (1.0 - x)};
}

}  // namespace attiguard::guidance
