#include "attiguard/dynamics/reaction_wheel_array.hpp"
#include "attiguard/lie/symmetric_eigen.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "attiguard/core/errors.hpp"

namespace attiguard::dynamics {

ReactionWheelArray::ReactionWheelArray(std::span<const ReactionWheel> wheels) {
  if (wheels.size() < 3 || wheels.size() > static_cast<std::size_t>(kMaxWheels)) {
    throw SetupError("reaction wheels: 3 to " + std::to_string(kMaxWheels) + " wheels");
  }
  count_ = static_cast<int>(wheels.size());
  lie::Mat3 AAt = lie::Mat3::Zero();
  for (int i = 0; i < count_; ++i) {
    ReactionWheel w = wheels[static_cast<std::size_t>(i)];
    const double n = w.axis_b.norm();
    if (!(n > 0.0) || !std::isfinite(n) || !(w.torque_max > 0.0) || !std::isfinite(w.torque_max) ||
        !(w.momentum_max > 0.0) || !std::isfinite(w.momentum_max) || !std::isfinite(w.momentum0) ||
        std::abs(w.momentum0) > w.momentum_max) {
      throw SetupError("reaction wheels: wheel " + std::to_string(i) +
                       " needs a non-zero axis, positive finite limits and |h(0)| <= momentum_max");
    }
    w.axis_b /= n;
    wheels_[static_cast<std::size_t>(i)] = w;
    AAt += w.axis_b * w.axis_b.transpose();
  }
  const lie::Vec3 sigma2 = lie::symmetric_eigenvalues(AAt);
  if (!(sigma2(0) > 1e-6 * sigma2(2))) {
    throw SetupError("reaction wheels: the spin axes do not span the three body axes");
  }
  const lie::Mat3 AAt_inv = AAt.inverse();
  for (int i = 0; i < count_; ++i) {
    rows_[static_cast<std::size_t>(i)] = AAt_inv * wheels_[static_cast<std::size_t>(i)].axis_b;
  }
}

lie::Vec3 ReactionWheelArray::body_torque(const WheelVector& u) const noexcept {
  lie::Vec3 tau = lie::Vec3::Zero();
  for (int i = 0; i < count_; ++i) tau += u[static_cast<std::size_t>(i)] * wheel(i).axis_b;
  return tau;
}

lie::Vec3 ReactionWheelArray::body_momentum(const WheelVector& h) const noexcept {
  return body_torque(h);
}

WheelVector ReactionWheelArray::allocate(const lie::Vec3& tau_b) const noexcept {
  WheelVector u{};
  for (int i = 0; i < count_; ++i) {
    const double limit = wheel(i).torque_max;
    u[static_cast<std::size_t>(i)] = std::clamp(allocation_row(i).dot(tau_b), -limit, limit);
  }
  return u;
}

std::array<ReactionWheel, 4> pyramid_wheels(double elevation, double torque_max,
                                            double momentum_max) noexcept {
  std::array<ReactionWheel, 4> w{};
  for (int i = 0; i < 4; ++i) {
    const double azimuth = (0.25 + 0.5 * i) * std::numbers::pi;
    w[static_cast<std::size_t>(i)] = {
        lie::Vec3(std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth),
                  std::sin(elevation)),
        torque_max, momentum_max, 0.0};
  }
  return w;
}

}  // namespace attiguard::dynamics
