#include "attiguard/governor/torque_slabs.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace attiguard::governor {

double TorqueSlabs::gauge(const lie::Vec3& tau_b) const noexcept {
  double g = tau_b.norm() / ball;
  for (int i = 0; i < count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    g = std::max(g, std::abs(rows[k].dot(tau_b)) / limits[k]);
  }
  return g;
}

double TorqueSlabs::inflated_gauge(const lie::Vec3& tau_b, double e) const noexcept {
  double g = (tau_b.norm() + e) / ball;
  for (int i = 0; i < count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    g = std::max(g, (std::abs(rows[k].dot(tau_b)) + rows[k].norm() * e) / limits[k]);
  }
  return g;
}

double TorqueSlabs::plan_gauge(const SlewPlan& plan, double rate_squared, double e) const noexcept {
  double g = inflated_gauge(lie::Vec3::Zero(), e);
  for (const SlewPlanNode& n : plan.nodes()) g = std::max(g, inflated_gauge(rate_squared * n.tau_b, e));
  for (const lie::Vec3& tau : plan.midpoint_torques()) g = std::max(g, inflated_gauge(rate_squared * tau, e));
  return g;
}

TorqueSlabs wheel_torque_slabs(const dynamics::ReactionWheelArray& array, double tau_max) noexcept {
  TorqueSlabs s;
  s.ball = tau_max;
  s.count = array.count();
  for (int i = 0; i < array.count(); ++i) {
    const auto k = static_cast<std::size_t>(i);
    s.rows[k] = array.allocation_row(i);
    s.limits[k] = array.wheel(i).torque_max;
  }
  return s;
}

}  // namespace attiguard::governor
