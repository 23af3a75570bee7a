#include "attiguard/plan/slew_problem.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Eigenvalues>

namespace attiguard::plan {

std::optional<std::string> slew_problem_error(const SlewProblem& problem,
                                              const PlannerOptions& options) {
  const Mat3& J = problem.J_b;
  if (!J.allFinite() || (J - J.transpose()).cwiseAbs().maxCoeff() > 1e-9 * J.cwiseAbs().maxCoeff()) {
    return "the inertia must be finite and symmetric";
  }
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(J);
  if (!(eig.eigenvalues().minCoeff() > 0.0)) return "the inertia must be positive definite";
  if (!lie::is_rotation(problem.R_start, 1e-6)) return "the start attitude is not a rotation";
  if (!lie::is_rotation(problem.R_target, 1e-6)) return "the target attitude is not a rotation";
  if (!(problem.tau_max > 0.0) || !std::isfinite(problem.tau_max)) {
    return "tau_max must be positive and finite";
  }
  if (!(problem.torque_headroom >= 0.0 && problem.torque_headroom < 1.0)) {
    return "the torque headroom must lie in [0, 1)";
  }
  if (!(problem.cone_margin >= 0.0 && problem.cone_margin < 0.5 * std::numbers::pi)) {
    return "the cone margin must lie in [0, 90) deg";
  }
  if (problem.cones.size() > static_cast<std::size_t>(governor::kMaxCones)) {
    return "at most 16 cones";
  }
  for (const governor::ConeConstraint& cone : problem.cones) {
    if (auto e = governor::cone_error(cone)) return *e;
  }
  if (options.intervals != 0 && (options.intervals < 4 || options.intervals > 2000)) {
    return "the number of intervals must lie in [4, 2000] (or 0: derived)";
  }
  if (options.dense_points_per_interval < 2 || options.dense_points_per_interval > 10000) {
    return "the dense check's points per interval must lie in [2, 10000]";
  }
  if (options.max_refinements < 0 || options.max_iterations < 1 ||
      !(options.max_solve_seconds > 0.0)) {
    return "the refinement, iteration and time limits must be positive";
  }
  return std::nullopt;
}

double tightened_cosine(const governor::ConeConstraint& cone, double tightening) noexcept {
  return std::cos(std::max(0.0, cone.theta_c - tightening));
}

double cone_angle_margin(const governor::ConeConstraint& cone, const Mat3& R_ib) noexcept {
  const Vec3 axis_i = R_ib * cone.axis_b;
  // atan2 of the cross and dot products: accurate at every angle (acos loses it near 0 and π).
  const double angle = std::atan2(cone.direction_i.cross(axis_i).norm(),
                                  cone.direction_i.dot(axis_i));
  return cone.theta_c - angle;
}

}  // namespace attiguard::plan
