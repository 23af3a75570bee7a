#include "attiguard/plan/cone_quadratic.hpp"

namespace attiguard::plan {

Eigen::Matrix4d cone_quadratic(const lie::Vec3& axis_b, const lie::Vec3& direction_i) noexcept {
  const double c = direction_i.dot(axis_b);
  const lie::Vec3 cross = axis_b.cross(direction_i);
  Eigen::Matrix4d M;
  M(0, 0) = c;
  M.block<1, 3>(0, 1) = cross.transpose();
  M.block<3, 1>(1, 0) = cross;
  M.block<3, 3>(1, 1) = axis_b * direction_i.transpose() + direction_i * axis_b.transpose() -
                        c * lie::Mat3::Identity();
  return M;
}

}  // namespace attiguard::plan
