#include "attiguard/guidance/error_frame.hpp"

#include <algorithm>
#include <cmath>

namespace attiguard::guidance {

namespace {
/// ‖n‖² below which the error direction counts as antiparallel to the chart's x axis
/// (‖n‖² = 2(1 + cos ϑ): ϑ within ≈ 1.4e-6 rad of π).
constexpr double kAntiparallelFloor = 1e-12;
}  // namespace

ErrorFrame error_frame(const Quat& q_ir, const Vec3& e_i, const Vec3& e_dot_i,
                       double e_floor) noexcept {
  ErrorFrame out;
  const double e_norm = e_i.norm();
  if (!(e_norm > 0.0)) {
    out.q_ie = q_ir;
    return out;
  }
  const Mat3 R_ri = lie::quat_to_rotation(q_ir).transpose();  // inertial → chart
  const Vec3 u = R_ri * (e_i / e_norm);                       // ê in chart coordinates
  // d/dt ê = (I − ê êᵀ) ė / ‖e‖, with ‖e‖ floored so the rate stays finite as ‖e‖ → 0.
  const Vec3 e_hat = e_i / e_norm;
  const Vec3 e_hat_dot = (e_dot_i - e_hat * e_hat.dot(e_dot_i)) / std::max(e_norm, e_floor);
  const Vec3 u_dot = R_ri * e_hat_dot;
  const Vec3 x = Vec3::UnitX();
  // n ∝ [cos(ϑ/2), k sin(ϑ/2)] ([Waypoint eq. (8)] with the erratum fixed): [1 + cos ϑ, k sin ϑ].
  Quat n;
  n(0) = 1.0 + x.dot(u);
  n.tail<3>() = x.cross(u);
  Quat n_dot;
  n_dot(0) = x.dot(u_dot);
  n_dot.tail<3>() = x.cross(u_dot);
  out.cos_chart = x.dot(u);
  if (!(n.squaredNorm() > kAntiparallelFloor)) {
    // ê (anti)parallel to −x of the chart: n → 0 and the shortest arc is not unique (ϑ = π,
    // erratum 3). Take the half turn about the chart's z axis, the limit of n/‖n‖ along x × u
    // ∥ z; its rate is that of the normalised form (finite, as ‖n‖ = 1 here). The guidance never
    // stays here: it re-anchors its chart as soon as cos ϑ < 0 (docs/waypoint.md, "Charts").
    n = Quat(0.0, 0.0, 0.0, 1.0);
  }
  out.q_ie = lie::quat_multiply(q_ir, n / n.norm());
  out.omega_e = angular_velocity_of_unnormalised(n, n_dot);
  return out;
}

Vec3 eq9_corrected_rate(const Quat& q_ie, const Vec3& e_i, const Vec3& e_dot_i) noexcept {
  const double e2 = e_i.squaredNorm();
  if (!(e2 > 0.0)) {
    return Vec3::Zero();
  }
  const Vec3 e_e(std::sqrt(e2), 0.0, 0.0);
  const Vec3 e_dot_e = lie::quat_to_rotation(q_ie).transpose() * e_dot_i;
  // S†(a) = S(a)ᵀ/‖a‖² = −S(a)/‖a‖², so −S†(a) b = a × b/‖a‖².
  return e_e.cross(e_dot_e) / e2;
}

Vec3 eq9_as_printed(const Quat& q_ie, const Vec3& e_i) noexcept {
  const double e2 = e_i.squaredNorm();
  if (!(e2 > 0.0)) {
    return Vec3::Zero();
  }
  const Vec3 e_e(std::sqrt(e2), 0.0, 0.0);
  const Vec3 r = lie::quat_to_rotation(q_ie).transpose() * e_i;  // = e^e by construction
  return e_e.cross(r) / e2;  // −S†(e^e) R_i^e e^i
}

Quat eq8_as_printed(const Vec3& e_i) noexcept {
  const Vec3 e_e(e_i.norm(), 0.0, 0.0);
  const double theta = std::acos(std::clamp(e_e.dot(e_i) / e_i.squaredNorm(), -1.0, 1.0));  // (10)
  const Vec3 k = e_e.cross(e_i).normalized();                                              // (11)
  Quat q;
  q(0) = std::sin(0.5 * theta);
  q.tail<3>() = k * std::cos(0.5 * theta);
  return q;
}

}  // namespace attiguard::guidance
