#pragma once
/// @file slew_plan.hpp
/// A planned rest-to-rest slew as the flight loop reads it (docs/slew-planner.md, "The plan as a
/// trajectory"): the nodes t_k of a direct transcription with the attitude quaternion q_k, the
/// body rate ω_k and its derivative ω̇_k, joined by the cubic Hermite interpolant of the
/// Hermite–Simpson transcription. Between nodes q(t) is the cubic through (q_k, q̇_k) and
/// (q_{k+1}, q̇_{k+1}) with q̇ = ½ q ⊗ [0, ω] [Waypoint eq. (4)], normalised; ω(t) is the
/// cubic through (ω_k, ω̇_k) and (ω_{k+1}, ω̇_{k+1}). The torque is the transcription's control,
/// linear between a node, its interval's midpoint and the next node: a convex combination of
/// torques the transcription kept within the bound, so the bound holds between them too.
/// ω̇(t) = J⁻¹(τ(t) − ω(t) × Jω(t)), the body's acceleration under that torque: what a tracking
/// law feeds forward is then the plan's torque (the derivative of the ω cubic would be the
/// quadratic through the node, midpoint and node accelerations, up to 25 % above a torque that
/// switches within the interval).
///
/// Built once at set-up (allocates); evaluate() is noexcept and allocation-free (flight loop).

#include <span>
#include <vector>

#include "attiguard/lie/quaternion.hpp"
#include "attiguard/lie/so3.hpp"

namespace attiguard::governor {

/// One node of a plan: time [s], q_ib (scalar-first, unit up to the transcription's error),
/// ω_b [rad/s], ω̇_b [rad/s²] and the control torque τ_b [N·m] (docs/slew-planner.md, "The plan
/// as a trajectory").
struct SlewPlanNode {
  double t{0.0};
  lie::Quat q_ib{lie::quat_identity()};
  lie::Vec3 omega_b{lie::Vec3::Zero()};
  lie::Vec3 omega_dot_b{lie::Vec3::Zero()};
  lie::Vec3 tau_b{lie::Vec3::Zero()};
};

/// The plan at one instant (docs/slew-planner.md, "The plan as a trajectory").
struct SlewPlanSample {
  lie::Quat q_ib{lie::quat_identity()};  ///< unit
  lie::Mat3 R_ib{lie::Mat3::Identity()};
  lie::Vec3 omega_b{lie::Vec3::Zero()};
  lie::Vec3 omega_dot_b{lie::Vec3::Zero()};
  lie::Vec3 tau_b{lie::Vec3::Zero()};  ///< the control torque [N·m]
};

/// A planned slew: nodes t_0 = 0 < t_1 < … < t_N = duration and the body's inertia J
/// (docs/slew-planner.md, "The plan as a trajectory").
class SlewPlan {
 public:
  SlewPlan() = default;
  /// Nodes in increasing time from t = 0, at least two, the control torque at each interval's
  /// midpoint (N of them; empty: the mean of its nodes') and the inertia J (kg·m², body frame).
  /// Throws SetupError when the nodes are not increasing from 0, a value is not finite or the
  /// midpoint torques are not one per interval.
  SlewPlan(std::vector<SlewPlanNode> nodes, std::vector<lie::Vec3> midpoint_tau_b,
           const lie::Mat3& J_b);

  /// The plan at time t (clamped to [0, duration]): cubic Hermite interpolant of the
  /// Hermite–Simpson transcription (docs/slew-planner.md, "The plan as a trajectory").
  [[nodiscard]] SlewPlanSample evaluate(double t) const noexcept;
  /// ω, ω̇ and τ at time t (the attitude left at its default): evaluate() without the
  /// quaternion's interpolation, for a feedforward that needs the rates only.
  [[nodiscard]] SlewPlanSample rates(double t) const noexcept;
  /// The interval k with t_k ≤ t ≤ t_{k+1} (t clamped to the plan; a binary search).
  [[nodiscard]] int interval_of(double t) const noexcept;
  /// ω, ω̇, τ of interval k at t into `out` (not the attitude); rates() finds k.
  void rates_in(int k, double t, SlewPlanSample& out) const noexcept;
  /// The plan at time t within interval k (t_k ≤ t ≤ t_{k+1}); evaluate() finds k.
  [[nodiscard]] SlewPlanSample evaluate_in(int k, double t) const noexcept;
  /// t_N: the slew's duration [s].
  [[nodiscard]] double duration() const noexcept {
    return nodes_.empty() ? 0.0 : nodes_.back().t;
  }
  /// The nodes (docs/slew-planner.md, "The plan as a trajectory").
  [[nodiscard]] std::span<const SlewPlanNode> nodes() const noexcept { return nodes_; }
  /// Number of intervals N.
  [[nodiscard]] int intervals() const noexcept { return static_cast<int>(nodes_.size()) - 1; }
  /// The control torque at each interval's midpoint [N·m].
  [[nodiscard]] std::span<const lie::Vec3> midpoint_torques() const noexcept {
    return midpoint_tau_b_;
  }
  /// The inertia J the plan was made for.
  [[nodiscard]] const lie::Mat3& inertia() const noexcept { return J_b_; }

 private:
  std::vector<SlewPlanNode> nodes_;
  std::vector<lie::Vec3> midpoint_tau_b_;
  lie::Mat3 J_b_{lie::Mat3::Identity()};
  lie::Mat3 J_inv_b_{lie::Mat3::Identity()};
  std::vector<lie::Quat> q_rate_;  ///< q̇_k = ½ q_k ⊗ [0, ω_k] of each node
};

}  // namespace attiguard::governor
