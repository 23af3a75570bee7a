#include "attiguard/lie/jacobians.hpp"

#include <cmath>

namespace attiguard::lie {

Mat3 left_jacobian(const Vec3& w) noexcept {
  const double t2 = w.squaredNorm();
  const double t = std::sqrt(t2);
  double a;  // (1 − cos θ)/θ²
  double b;  // (θ − sin θ)/θ³
  if (t < 1e-4) {
    a = 0.5 - t2 / 24.0 + t2 * t2 / 720.0;
    b = 1.0 / 6.0 - t2 / 120.0 + t2 * t2 / 5040.0;
  } else {
    a = (1.0 - std::cos(t)) / t2;
    b = (t - std::sin(t)) / (t2 * t);
  }
  const Mat3 W = hat(w);
  return Mat3::Identity() + a * W + b * (W * W);
}

Mat3 left_jacobian_inverse(const Vec3& w) noexcept {
  const double t2 = w.squaredNorm();
  const double t = std::sqrt(t2);
  double c;  // 1/θ² − (1 + cos θ)/(2θ sin θ)
  if (t < 1e-4) {
    c = 1.0 / 12.0 + t2 / 720.0 + t2 * t2 / 30240.0;
  } else {
    c = 1.0 / t2 - (1.0 + std::cos(t)) / (2.0 * t * std::sin(t));
  }
  const Mat3 W = hat(w);
  return Mat3::Identity() - 0.5 * W + c * (W * W);
}

Mat3 right_jacobian(const Vec3& w) noexcept { return left_jacobian(-w); }

Mat3 right_jacobian_inverse(const Vec3& w) noexcept { return left_jacobian_inverse(-w); }

}  // namespace attiguard::lie
