#pragma once
/// @file axis_angle.hpp
/// Axis-angle representation and its conversions to rotation matrices and rotation vectors.

#include "attiguard/lie/so3.hpp"

namespace attiguard::lie {

/// A rotation by `angle` (rad) about the unit vector `axis` (right-hand rule).
struct AxisAngle {
  Vec3 axis{Vec3::UnitX()};
  double angle{0.0};
};

/// R = exp(angle · axis^) for a unit axis (Rodrigues).
[[nodiscard]] Mat3 rotation_from_axis_angle(const AxisAngle& aa) noexcept;

/// Axis and angle ∈ [0, π] of R; for the identity, the axis is e_x and the angle 0.
[[nodiscard]] AxisAngle axis_angle_from_rotation(const Mat3& R) noexcept;

/// Rotation vector angle · axis.
[[nodiscard]] inline Vec3 rotation_vector(const AxisAngle& aa) noexcept { return aa.angle * aa.axis; }

/// Axis-angle of a rotation vector w (axis e_x when w = 0).
[[nodiscard]] AxisAngle axis_angle_from_rotation_vector(const Vec3& w) noexcept;

}  // namespace attiguard::lie
