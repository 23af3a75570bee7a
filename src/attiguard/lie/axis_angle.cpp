#include "attiguard/lie/axis_angle.hpp"

namespace attiguard::lie {

Mat3 rotation_from_axis_angle(const AxisAngle& aa) noexcept { return exp(aa.angle * aa.axis); }

AxisAngle axis_angle_from_rotation_vector(const Vec3& w) noexcept {
  const double angle = w.norm();
  if (angle == 0.0) {
    return AxisAngle{Vec3::UnitX(), 0.0};
  }
  return AxisAngle{w / angle, angle};
}

AxisAngle axis_angle_from_rotation(const Mat3& R) noexcept {
  return axis_angle_from_rotation_vector(log(R));
}

}  // namespace attiguard::lie
