#pragma once
/// @file slew_planner.hpp
/// The slew planner (docs/slew-planner.md): a near time-optimal rest-to-rest slew that keeps
/// every cone and the torque bound between the nodes too. The way around the cones from a roadmap
/// (initial_path.hpp), refined by a direct transcription solved by IPOPT
/// (transcription_nlp.hpp), checked densely and re-solved with locally tightened constraints
/// until the dense check passes. Set-up code: it allocates and may take milliseconds to seconds;
/// never call it in a flight loop.

#include <string>

#include "attiguard/governor/slew_plan.hpp"
#include "attiguard/plan/slew_problem.hpp"

namespace attiguard::plan {

/// The dense check of a plan (docs/slew-planner.md, "Dense check"): the smallest cone margin and
/// the largest ‖τ‖/τ_max over `points_per_interval` points of every interval.
struct DenseCheck {
  double smallest_cone_margin{0.0};  ///< [rad]; +∞ (a large number) without cones
  int smallest_margin_cone{-1};      ///< its cone's index, −1 without cones
  double smallest_margin_time{0.0};  ///< [s]
  double largest_torque_ratio{0.0};  ///< max ‖τ‖/τ_max
  double largest_torque_time{0.0};   ///< [s]
  /// The rigid body flown from each node with the plan's torque (RK4, one step per dense point):
  /// the largest angle between its attitude and the plan's within the interval [rad]. The
  /// plan's dynamic consistency (docs/slew-planner.md, "Dense check").
  double largest_attitude_deviation{0.0};
};

/// Checks `plan` against the problem's cones and τ_max (docs/slew-planner.md, "Dense check").
[[nodiscard]] DenseCheck dense_check(const governor::SlewPlan& plan, const SlewProblem& problem,
                                     int points_per_interval);

/// What the planner did (plan.json, docs/slew-planner.md, "Outputs").
struct PlanReport {
  double duration{0.0};               ///< [s]
  double bang_bang_time{0.0};         ///< the eigenaxis bang-bang time at τ_max [s]
  double ratio{0.0};                  ///< duration / bang_bang_time
  DenseCheck check;                   ///< the dense check of the returned plan
  int intervals{0};                   ///< N
  int path_waypoints{0};              ///< interior waypoints of the initial path (0: eigenaxis)
  int ways_tried{0};                  ///< initial paths refined
  int solves{0};                      ///< IPOPT solves in all
  int iterations{0};                  ///< IPOPT iterations in all
  /// Solves repeated because the plan came near a cone left out of the program far from the
  /// initial guess (docs/slew-planner.md, "Speed").
  int cones_reimposed{0};
  std::string solver_status;          ///< the accepted solve's status
  double planning_seconds{0.0};       ///< wall time of plan_slew
  int roadmap_attitudes{0};           ///< attitudes of the roadmap
};

/// A plan and its report.
struct PlannedSlew {
  governor::SlewPlan plan;
  PlanReport report;
};

/// Plans the slew (docs/slew-planner.md). Throws SetupError for a malformed problem,
/// VerificationFailure (exit 4) when there is no admissible path (the start or the target
/// violates a cone or its margin, or no way around the cones is found), NumericalError (exit 3)
/// when the solver does not converge or the dense check still fails after the refinements
/// (with IPOPT's status); never returns a plan that fails the dense check.
[[nodiscard]] PlannedSlew plan_slew(const SlewProblem& problem,
                                    const PlannerOptions& options = {});

}  // namespace attiguard::plan
