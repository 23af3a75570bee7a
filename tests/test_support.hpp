#pragma once
/// Shared helpers for the test suite: random rotations and finite differences.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <random>

#include "attiguard/lie/so3.hpp"

namespace attiguard::test {

/// Deterministic generator for property tests.
inline std::mt19937_64& rng() {
  static std::mt19937_64 gen(20261122);
  return gen;
}

/// Uniform vector in the ball of radius r.
inline Eigen::Vector3d random_vector_in_ball(double r) {
  std::normal_distribution<double> n(0.0, 1.0);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Eigen::Vector3d v(n(rng()), n(rng()), n(rng()));
  return v.normalized() * r * std::cbrt(u(rng()));
}

/// Uniformly distributed unit vector.
inline Eigen::Vector3d random_unit() { return random_vector_in_ball(1.0).normalized(); }

/// Uniformly distributed rotation (normalised Gaussian quaternion).
inline Eigen::Matrix3d random_rotation() {
  std::normal_distribution<double> n(0.0, 1.0);
  Eigen::Quaterniond q(n(rng()), n(rng()), n(rng()), n(rng()));
  q.normalize();
  return q.toRotationMatrix();
}

/// Central finite-difference Jacobian of f: R^n → R^m at x, step h.
template <class F, int N>
Eigen::MatrixXd numerical_jacobian(F&& f, const Eigen::Matrix<double, N, 1>& x, double h = 1e-6) {
  const auto f0 = f(x);
  Eigen::MatrixXd Jac(f0.size(), x.size());
  for (int i = 0; i < x.size(); ++i) {
    Eigen::Matrix<double, N, 1> xp = x;
    Eigen::Matrix<double, N, 1> xm = x;
    xp(i) += h;
    xm(i) -= h;
    Jac.col(i) = (f(xp) - f(xm)) / (2.0 * h);
  }
  return Jac;
}

}  // namespace attiguard::test
