#include "attiguard/lie/so3.hpp"

#include <Eigen/LU>
#include <Eigen/SVD>
#include <cmath>

namespace attiguard::lie {

Mat3 hat(const Vec3& x) noexcept {
  Mat3 X;
  X << 0.0, -x.z(), x.y(),  //
      x.z(), 0.0, -x.x(),   //
      -x.y(), x.x(), 0.0;
  return X;
}

Vec3 vee(const Mat3& X) noexcept { return Vec3(X(2, 1), X(0, 2), X(1, 0)); }

Mat3 sk(const Mat3& A) noexcept { return 0.5 * (A - A.transpose()); }

Mat3 exp(const Vec3& w) noexcept {
  const double theta2 = w.squaredNorm();
  const double theta = std::sqrt(theta2);
  double a;  // sin θ / θ
  double b;  // (1 − cos θ) / θ²
  if (theta < 1e-4) {
    a = 1.0 - theta2 / 6.0 + theta2 * theta2 / 120.0;
    b = 0.5 - theta2 / 24.0 + theta2 * theta2 / 720.0;
  } else {
    a = std::sin(theta) / theta;
    b = (1.0 - std::cos(theta)) / theta2;
  }
  const Mat3 W = hat(w);
  return Mat3::Identity() + a * W + b * (W * W);
}

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

double phi(const Mat3& R) noexcept { return 0.5 * (3.0 - R.trace()); }

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
