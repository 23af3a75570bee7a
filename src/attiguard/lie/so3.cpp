#include "attiguard/lie/so3.hpp"

#include <Eigen/LU>
#include <Eigen/SVD>
#include <cmath>

namespace attiguard::lie {

Vec3 log(const Mat3& R) noexcept {
  const Vec3 s2 = vee(R - R.transpose());  // 2 sin θ k
  const double sin_theta = 0.5 * s2.norm();
  const double cos_theta = 0.5 * (R.trace() - 1.0);
  const double theta = std::atan2(sin_theta, cos_theta);
  if (theta < 1e-4) {
    // θ / sin θ = 1 + θ²/6 + 7θ⁴/360 + O(θ⁶)
    const double t2 = theta * theta;
    return 0.5 * (1.0 + t2 / 6.0 + 7.0 * t2 * t2 / 360.0) * s2;
  }
  if (cos_theta > 0.0) {
    return (0.5 * theta / sin_theta) * s2;
  }
  // θ ≥ π/2: B = (R + Rᵀ)/2 − cos θ I = (1 − cos θ) k kᵀ. Take the largest diagonal entry.
  const Mat3 B = 0.5 * (R + R.transpose()) - cos_theta * Mat3::Identity();
  const double one_minus_cos = 1.0 - cos_theta;
  Eigen::Index j = 0;
  B.diagonal().maxCoeff(&j);
  Vec3 k = B.col(j) / std::sqrt(B(j, j) * one_minus_cos);
  k.normalize();
  if (k.dot(s2) < 0.0) {
    k = -k;
  }
  return theta * k;
}

double distance(const Mat3& R1, const Mat3& R2) noexcept {
  return log(R1.transpose() * R2).norm();
}

Mat3 project_to_so3(const Mat3& M) noexcept {
  Eigen::JacobiSVD<Mat3> svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Mat3 D = Mat3::Identity();
  D(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
  return svd.matrixU() * D * svd.matrixV().transpose();
}

double orthonormality_error(const Mat3& M) noexcept {
  return (M.transpose() * M - Mat3::Identity()).norm();
}

bool is_rotation(const Mat3& M, double tol) noexcept {
  return M.allFinite() && orthonormality_error(M) <= tol && M.determinant() > 0.0;
}

}  // namespace attiguard::lie
