#include "attiguard/lie/quaternion.hpp"

#include <cmath>

namespace attiguard::lie {

Eigen::Matrix4d quat_product_matrix(const Quat& p) noexcept {
  const double eta = p(0);
  const Vec3 eps = p.tail<3>();
  Eigen::Matrix4d T;
  T(0, 0) = eta;
  T.block<1, 3>(0, 1) = -eps.transpose();
  T.block<3, 1>(1, 0) = eps;
  T.block<3, 3>(1, 1) = eta * Mat3::Identity() + hat(eps);
  return T;
}

Quat quat_multiply(const Quat& p, const Quat& q) noexcept {
  const double ep = p(0);
  const double eq = q(0);
  const Vec3 vp = p.tail<3>();
  const Vec3 vq = q.tail<3>();
  Quat r;
  r(0) = ep * eq - vp.dot(vq);
  r.tail<3>() = ep * vq + eq * vp + vp.cross(vq);
  return r;
}

Quat quat_conjugate(const Quat& q) noexcept { return Quat(q(0), -q(1), -q(2), -q(3)); }

Mat3 quat_to_rotation(const Quat& q) noexcept {
  // R = I + 2η ε̂ + 2 ε̂², written out entry by entry (ε̂² = εεᵀ − ‖ε‖² I).
  const Quat u = q / q.norm();
  const double w = u(0), x = u(1), y = u(2), z = u(3);
  const double xx = x * x, yy = y * y, zz = z * z;
  const double xy = x * y, xz = x * z, yz = y * z, wx = w * x, wy = w * y, wz = w * z;
  Mat3 R;
  R << 1.0 - 2.0 * (yy + zz), 2.0 * (xy - wz), 2.0 * (xz + wy),  //
      2.0 * (xy + wz), 1.0 - 2.0 * (xx + zz), 2.0 * (yz - wx),    //
      2.0 * (xz - wy), 2.0 * (yz + wx), 1.0 - 2.0 * (xx + yy);
  return R;
}

Quat rotation_to_quat(const Mat3& R) noexcept {
  // Shepperd: pick the largest of 4η², 4ε_x², 4ε_y², 4ε_z² to divide by.
  const double tr = R.trace();
  const double d0 = 1.0 + tr;
  const double d1 = 1.0 + 2.0 * R(0, 0) - tr;
  const double d2 = 1.0 + 2.0 * R(1, 1) - tr;
  const double d3 = 1.0 + 2.0 * R(2, 2) - tr;
  Quat q;
  if (d0 >= d1 && d0 >= d2 && d0 >= d3) {
    const double s = 2.0 * std::sqrt(d0);  // 4η
    q << 0.25 * s, (R(2, 1) - R(1, 2)) / s, (R(0, 2) - R(2, 0)) / s, (R(1, 0) - R(0, 1)) / s;
  } else if (d1 >= d2 && d1 >= d3) {
    const double s = 2.0 * std::sqrt(d1);  // 4ε_x
    q << (R(2, 1) - R(1, 2)) / s, 0.25 * s, (R(0, 1) + R(1, 0)) / s, (R(0, 2) + R(2, 0)) / s;
  } else if (d2 >= d3) {
    const double s = 2.0 * std::sqrt(d2);  // 4ε_y
    q << (R(0, 2) - R(2, 0)) / s, (R(0, 1) + R(1, 0)) / s, 0.25 * s, (R(1, 2) + R(2, 1)) / s;
  } else {
    const double s = 2.0 * std::sqrt(d3);  // 4ε_z
    q << (R(1, 0) - R(0, 1)) / s, (R(0, 2) + R(2, 0)) / s, (R(1, 2) + R(2, 1)) / s, 0.25 * s;
  }
  if (q(0) < 0.0) {
    q = -q;
  }
  return q / q.norm();
}

Quat quat_from_axis_angle(const Vec3& unit_axis, double angle) noexcept {
  Quat q;
  q(0) = std::cos(0.5 * angle);
  q.tail<3>() = std::sin(0.5 * angle) * unit_axis;
  return q;
}

Quat quat_from_rotation_vector(const Vec3& w) noexcept {
  const double t2 = w.squaredNorm();
  const double t = std::sqrt(t2);
  Quat q;
  q(0) = std::cos(0.5 * t);
  // sin(θ/2)/θ = ½ (1 − θ²/24 + θ⁴/1920 − …)
  const double c = t < 1e-4 ? 0.5 * (1.0 - t2 / 24.0 + t2 * t2 / 1920.0) : std::sin(0.5 * t) / t;
  q.tail<3>() = c * w;
  return q;
}

Vec3 rotation_vector_from_quat(const Quat& q_in) noexcept {
  Quat q = q_in / q_in.norm();
  if (q(0) < 0.0) {
    q = -q;
  }
  const Vec3 eps = q.tail<3>();
  const double s = eps.norm();            // sin(θ/2)
  const double theta = 2.0 * std::atan2(s, q(0));  // ∈ [0, π]
  if (s < 1e-8) {
    // θ/sin(θ/2) → 2 (1 + θ²/24) for small θ
    return 2.0 * (1.0 + theta * theta / 24.0) * eps;
  }
  return (theta / s) * eps;
}

}  // namespace attiguard::lie
