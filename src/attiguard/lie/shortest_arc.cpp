#include "attiguard/lie/shortest_arc.hpp"

#include <cmath>

namespace attiguard::lie {

Vec3 any_orthogonal(const Vec3& a) noexcept {
  Eigen::Index j = 0;
  a.cwiseAbs().minCoeff(&j);
  const Vec3 o = a.cross(Vec3::Unit(j));
  const double n = o.norm();
  return n > 0.0 ? Vec3(o / n) : Vec3::UnitX();
}

Quat shortest_arc_quat(const Vec3& a, const Vec3& b) noexcept {
  const double na = a.norm();
  const double nb = b.norm();
  if (!(na > 0.0) || !(nb > 0.0)) {
    return quat_identity();
  }
  const Vec3 ua = a / na;
  const Vec3 ub = b / nb;
  const double c = ua.dot(ub);  // cos ϑ
  Quat q;
  if (c >= 0.0) {
    const Vec3 cr = ua.cross(ub);  // k sin ϑ
    // η = cos(ϑ/2) = √((1 + cos ϑ)/2) is well conditioned here, and ε = k sin ϑ / (2η) is exact
    // and smooth through ϑ = 0.
    q(0) = std::sqrt(0.5 * (1.0 + c));
    q.tail<3>() = cr / (2.0 * q(0));
    return q;
  }
  // ϑ > π/2: the cross product of nearly anti-parallel vectors loses its direction to
  // cancellation, but b̂ − (â·b̂) â (the part of b̂ orthogonal to â) keeps full absolute accuracy.
  // Take the axis from it and ϑ from atan2, so that R â = b̂ holds to rounding even near ϑ = π.
  const Vec3 b_perp = ub - c * ua;
  const double s = b_perp.norm();  // sin ϑ
  const double theta = std::atan2(s, c);
  const Vec3 axis = ua.cross(b_perp);
  const double n_axis = axis.norm();
  const Vec3 k = n_axis > 1e-300 ? Vec3(axis / n_axis) : any_orthogonal(ua);
  q(0) = std::cos(0.5 * theta);
  q.tail<3>() = std::sin(0.5 * theta) * k;
  return q;
}

Mat3 shortest_arc(const Vec3& a, const Vec3& b) noexcept {
  return quat_to_rotation(shortest_arc_quat(a, b));
}

}  // namespace attiguard::lie
