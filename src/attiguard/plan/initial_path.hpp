#pragma once
/// @file initial_path.hpp
/// The way around the cones (docs/slew-planner.md, "The initial path"): a chain of eigenaxis
/// (geodesic) segments R_0 → W_1 → … → R_d whose attitudes keep every cone with a clearance,
/// found by a lazy roadmap search over a deterministic set of attitudes around R_0, R_d and
/// their geodesic midpoint. The eigenaxis R_0 → R_d itself when it is free.

#include <string>
#include <vector>

#include "attiguard/lie/quaternion.hpp"
#include "attiguard/plan/slew_problem.hpp"

namespace attiguard::plan {

/// Eigenaxis segments between consecutive quaternions (sign-continuous: q_{i+1} ⊗ … is the
/// short way from q_i), from q(R_0) to ±q(R_d).
struct AttitudePath {
  std::vector<lie::Quat> waypoints;
  double angle{0.0};  ///< Σ of the segments' angles [rad]
};

/// The result of the search: the paths found (best first, at most the count asked for, of
/// different ways around the cones) and the number of attitudes and segments examined.
struct PathSearch {
  std::vector<AttitudePath> paths;
  int attitudes{0};
  int segments_checked{0};
};

/// Whether every attitude of the geodesic q_a → q_b, sampled at most `step` [rad] apart, keeps
/// each cone with `clearance` beyond the problem's cone margin, relaxed linearly to the margin
/// alone within `clearance` of R_0 and R_d (docs/slew-planner.md, "The initial path").
[[nodiscard]] bool segment_is_free(const SlewProblem& problem, const lie::Quat& q_a,
                                   const lie::Quat& q_b, double clearance, double step);

/// Searches up to `count` paths of different ways around the cones (docs/slew-planner.md,
/// "The initial path"). Returns none when the roadmap holds no free path.
[[nodiscard]] PathSearch find_paths(const SlewProblem& problem, int count);

}  // namespace attiguard::plan
