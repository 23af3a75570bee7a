#pragma once
/// @file quaternion.hpp
/// Unit quaternions, scalar-first Hamilton convention q = [η, ε] [Waypoint Sec. II-A].
///
/// q = [cos(θ/2), k sin(θ/2)] rotates by θ about k and corresponds to
/// R(q) = I + 2η S(ε) + 2 S(ε)² [Waypoint eq. (12)]; R maps body to inertial when q = q_ib.
/// Eigen::Quaterniond stores [x, y, z, w]; cross that boundary only through to_eigen/from_eigen.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "attiguard/lie/so3.hpp"

namespace attiguard::lie {

/// Scalar-first unit quaternion [η, ε_x, ε_y, ε_z].
using Quat = Eigen::Vector4d;

/// Identity quaternion [1, 0, 0, 0].
[[nodiscard]] inline Quat quat_identity() noexcept { return Quat(1.0, 0.0, 0.0, 0.0); }

/// The 4×4 left-product matrix T(q) of [Waypoint eq. (1)]: p ⊗ q = T(p) q.
[[nodiscard]] Eigen::Matrix4d quat_product_matrix(const Quat& p) noexcept;

/// Hamilton product p ⊗ q = T(p) q [Waypoint eq. (1)]; R(p ⊗ q) = R(p) R(q).
[[nodiscard]] Quat quat_multiply(const Quat& p, const Quat& q) noexcept;

/// Conjugate [η, −ε], the inverse of a unit quaternion [Waypoint Sec. II-A].
[[nodiscard]] Quat quat_conjugate(const Quat& q) noexcept;

/// Rotation matrix R(q) = I + 2η S(ε) + 2 S(ε)² [Waypoint eq. (12)]; q need not be
/// exactly unit: it is normalised first.
[[nodiscard]] Mat3 quat_to_rotation(const Quat& q) noexcept;

/// Quaternion of a rotation matrix (Shepperd's method, numerically stable for every R), with the
/// sign chosen so that η ≥ 0.
[[nodiscard]] Quat rotation_to_quat(const Mat3& R) noexcept;

/// q = [cos(θ/2), k sin(θ/2)] for a unit axis k [Waypoint Sec. II-A].
[[nodiscard]] Quat quat_from_axis_angle(const Vec3& unit_axis, double angle) noexcept;

/// Quaternion of the rotation vector w = θ k (series near θ = 0).
[[nodiscard]] Quat quat_from_rotation_vector(const Vec3& w) noexcept;

/// Rotation vector θ k with θ ∈ [0, π] of a unit quaternion (q and −q give the same result).
[[nodiscard]] Vec3 rotation_vector_from_quat(const Quat& q) noexcept;

/// Named conversion to Eigen's quaternion type (whose coefficient storage is [x, y, z, w]).
[[nodiscard]] inline Eigen::Quaterniond to_eigen(const Quat& q) noexcept {
  return Eigen::Quaterniond(q(0), q(1), q(2), q(3));
}
/// Named conversion from Eigen's quaternion type.
[[nodiscard]] inline Quat from_eigen(const Eigen::Quaterniond& q) noexcept {
  return Quat(q.w(), q.x(), q.y(), q.z());
}

}  // namespace attiguard::lie
