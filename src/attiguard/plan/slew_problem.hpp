#pragma once
/// @file slew_problem.hpp
/// The rest-to-rest slew the planner solves (docs/slew-planner.md, "The problem"): a rigid body
/// J [PET-ERG eq. (1)] from R_0 to R_d, at rest at both ends, with ‖τ‖₂ ≤ τ_max, pointing
/// cones [PET-ERG eq. (2b)] on body axes, a torque headroom and a cone margin.

#include <optional>
#include <string>
#include <vector>

#include "attiguard/governor/cone_constraint.hpp"
#include "attiguard/lie/so3.hpp"

namespace attiguard::plan {

using lie::Mat3;
using lie::Vec3;

/// The direct transcription of the slew (docs/slew-planner.md, "Transcription").
enum class Transcription {
  hermite_simpson,  ///< separated Hermite–Simpson: nodes and midpoints (the planner's own)
  trapezoid,        ///< trapezoidal collocation (the independent fine-mesh check)
};

/// A rest-to-rest slew problem (docs/slew-planner.md, "The problem").
struct SlewProblem {
  Mat3 J_b{Mat3::Identity()};      ///< inertia [kg·m²], body frame, symmetric positive definite
  Mat3 R_start{Mat3::Identity()};  ///< R_0 (body → inertial), at rest
  Mat3 R_target{Mat3::Identity()}; ///< R_d (body → inertial), at rest
  double tau_max{1.0};             ///< ‖τ‖₂ ≤ τ_max [N·m] (a wheel polytope: its inscribed ball)
  /// Pointing cones a_cᵀ R a_b ≥ cos θ_c [PET-ERG eq. (2b)] (keep-out: a_c = −s, θ_c = π − α).
  std::vector<governor::ConeConstraint> cones;
  double torque_headroom{0.05};  ///< the plan keeps ‖τ‖ ≤ (1 − headroom) τ_max, headroom ∈ [0, 1)
  double cone_margin{0.0};       ///< the plan keeps every cone with this angle to spare [rad]
};

/// How the planner works (docs/slew-planner.md, "Options").
struct PlannerOptions {
  int intervals{0};  ///< N (0: derived from the path, docs/slew-planner.md "Options")
  Transcription transcription{Transcription::hermite_simpson};
  int dense_points_per_interval{100};  ///< the dense check's points per interval
  int max_refinements{6};              ///< re-solves after a failed dense check
  int max_iterations{800};             ///< IPOPT's max_iter per solve
  double max_solve_seconds{60.0};      ///< IPOPT's max_cpu_time per solve [s]
  bool try_both_sides{true};  ///< also refine the best path of another way around the cones
};

/// Why a slew problem is malformed (J not symmetric positive definite and finite, a rotation
/// that is not one, τ_max ≤ 0, a bad cone, headroom ∉ [0, 1), margin < 0 or ≥ 90°, too many
/// intervals), or nullopt. Set-up code (allocates).
[[nodiscard]] std::optional<std::string> slew_problem_error(const SlewProblem& problem,
                                                            const PlannerOptions& options);

/// cos of the cone's half-angle tightened by `tightening` [rad]: the planner's constraint
/// a_cᵀ R a_b ≥ cos(θ_c − tightening) (docs/slew-planner.md, "Between the nodes").
[[nodiscard]] double tightened_cosine(const governor::ConeConstraint& cone,
                                      double tightening) noexcept;

/// The angle by which R keeps the cone: θ_c − ∠(a_c, R a_b) [rad], ≥ 0 when kept
/// (docs/slew-planner.md, "Dense check").
[[nodiscard]] double cone_angle_margin(const governor::ConeConstraint& cone,
                                       const Mat3& R_ib) noexcept;

}  // namespace attiguard::plan
