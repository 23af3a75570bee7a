#include "attiguard/governor/slew_plan.hpp"

#include <algorithm>
#include <cmath>

#include "attiguard/core/errors.hpp"

namespace attiguard::governor {

namespace {

/// q̇ = ½ q ⊗ [0, ω] [Waypoint eq. (4)].
lie::Quat quaternion_rate(const lie::Quat& q, const lie::Vec3& omega_b) noexcept {
  const lie::Vec3 eps = q.tail<3>();
  lie::Quat rate;
  rate(0) = -0.5 * eps.dot(omega_b);
  rate.tail<3>() = 0.5 * (q(0) * omega_b + eps.cross(omega_b));
  return rate;
}

/// Cubic Hermite basis on s ∈ [0, 1] for an interval of length h: value weights of
/// (y0, h·y0', y1, h·y1') and their s-derivatives.
struct HermiteBasis {
  double h00, h10, h01, h11;
  double d00, d10, d01, d11;
};

HermiteBasis hermite_basis(double s) noexcept {
  const double s2 = s * s;
  const double s3 = s2 * s;
  return {2.0 * s3 - 3.0 * s2 + 1.0, s3 - 2.0 * s2 + s,     -2.0 * s3 + 3.0 * s2,
          s3 - s2,                   6.0 * s2 - 6.0 * s,   3.0 * s2 - 4.0 * s + 1.0,
          -6.0 * s2 + 6.0 * s,       3.0 * s2 - 2.0 * s};
}

}  // namespace

SlewPlan::SlewPlan(std::vector<SlewPlanNode> nodes, std::vector<lie::Vec3> midpoint_tau_b,
                   const lie::Mat3& J_b)
    : nodes_(std::move(nodes)), midpoint_tau_b_(std::move(midpoint_tau_b)), J_b_(J_b) {
  if (nodes_.size() < 2) throw SetupError("a slew plan needs at least two nodes");
  if (nodes_.front().t != 0.0) throw SetupError("a slew plan starts at t = 0");
  for (std::size_t k = 0; k < nodes_.size(); ++k) {
    const SlewPlanNode& n = nodes_[k];
    if (!std::isfinite(n.t) || !n.q_ib.allFinite() || !n.omega_b.allFinite() ||
        !n.omega_dot_b.allFinite() || !n.tau_b.allFinite() || !(n.q_ib.norm() > 0.5)) {
      throw SetupError("a slew plan node is not finite");
    }
    if (k > 0 && !(n.t > nodes_[k - 1].t)) {
      throw SetupError("the nodes of a slew plan must be in increasing time");
    }
  }
  if (!J_b_.allFinite()) throw SetupError("a slew plan's inertia is not finite");
  if (midpoint_tau_b_.empty()) {
    for (std::size_t k = 0; k + 1 < nodes_.size(); ++k) {
      midpoint_tau_b_.push_back(0.5 * (nodes_[k].tau_b + nodes_[k + 1].tau_b));
    }
  }
  J_inv_b_ = J_b_.inverse();
  q_rate_.reserve(nodes_.size());
  for (const SlewPlanNode& n : nodes_) q_rate_.push_back(quaternion_rate(n.q_ib, n.omega_b));
  if (midpoint_tau_b_.size() + 1 != nodes_.size()) {
    throw SetupError("a slew plan needs one midpoint torque per interval");
  }
  for (const lie::Vec3& tau : midpoint_tau_b_) {
    if (!tau.allFinite()) throw SetupError("a slew plan's midpoint torque is not finite");
  }
}

void SlewPlan::rates_in(int k, double t, SlewPlanSample& out) const noexcept {
  const SlewPlanNode& a = nodes_[static_cast<std::size_t>(k)];
  const SlewPlanNode& b = nodes_[static_cast<std::size_t>(k + 1)];
  const double h = b.t - a.t;
  const double s = std::clamp((t - a.t) / h, 0.0, 1.0);
  const HermiteBasis w = hermite_basis(s);
  out.omega_b = w.h00 * a.omega_b + w.h10 * h * a.omega_dot_b + w.h01 * b.omega_b +
                w.h11 * h * b.omega_dot_b;
  const lie::Vec3& tau_mid = midpoint_tau_b_[static_cast<std::size_t>(k)];
  out.tau_b = s < 0.5 ? (1.0 - 2.0 * s) * a.tau_b + 2.0 * s * tau_mid
                      : (2.0 - 2.0 * s) * tau_mid + (2.0 * s - 1.0) * b.tau_b;
  // The body's acceleration under the plan's torque (the derivative of the ω cubic is the
  // quadratic through the node, midpoint and node accelerations, which overshoots a torque that
  // switches within the interval by up to 25 %).
  out.omega_dot_b = J_inv_b_ * (out.tau_b - out.omega_b.cross(J_b_ * out.omega_b));
}

SlewPlanSample SlewPlan::evaluate_in(int k, double t) const noexcept {
  const SlewPlanNode& a = nodes_[static_cast<std::size_t>(k)];
  const SlewPlanNode& b = nodes_[static_cast<std::size_t>(k + 1)];
  const double h = b.t - a.t;
  const double s = std::clamp((t - a.t) / h, 0.0, 1.0);
  const HermiteBasis w = hermite_basis(s);
  const lie::Quat& qa_rate = q_rate_[static_cast<std::size_t>(k)];
  const lie::Quat& qb_rate = q_rate_[static_cast<std::size_t>(k + 1)];
  const lie::Quat q = w.h00 * a.q_ib + w.h10 * h * qa_rate + w.h01 * b.q_ib + w.h11 * h * qb_rate;
  SlewPlanSample out;
  out.q_ib = q / q.norm();
  out.R_ib = lie::quat_to_rotation(out.q_ib);
  rates_in(k, t, out);
  return out;
}

int SlewPlan::interval_of(double t) const noexcept {
  // The interval k with t_k ≤ t ≤ t_{k+1}: the first node after t, minus one.
  const auto after = std::upper_bound(nodes_.begin(), nodes_.end(), t,
                                      [](double v, const SlewPlanNode& n) { return v < n.t; });
  return std::clamp(static_cast<int>(after - nodes_.begin()) - 1, 0, intervals() - 1);
}

SlewPlanSample SlewPlan::evaluate(double t) const noexcept {
  if (nodes_.size() < 2) return {};
  const double tc = std::clamp(t, 0.0, duration());
  return evaluate_in(interval_of(tc), tc);
}

SlewPlanSample SlewPlan::rates(double t) const noexcept {
  SlewPlanSample out;
  if (nodes_.size() < 2) return out;
  const double tc = std::clamp(t, 0.0, duration());
  rates_in(interval_of(tc), tc, out);
  return out;
}

}  // namespace attiguard::governor
