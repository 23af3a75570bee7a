#pragma once
/// @file transcription_nlp.hpp
/// The slew's direct transcription as a nonlinear program, solved by IPOPT with exact sparse
/// first and second derivatives (docs/slew-planner.md, "Transcription", "Derivatives"). All
/// quantities are in the planner's scaled units (docs/slew-planner.md, "Scaling"): time by
/// t_s, torque by the torque limit, J̄ = J/(τ_s t_s²); the torque constraint is ‖ū‖ ≤ 1.
///
/// IPOPT is not thread-safe (docs/slew-planner.md, "Speed"): every solve of the process is
/// serialised behind one mutex.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "attiguard/lie/quaternion.hpp"
#include "attiguard/plan/point_dynamics.hpp"
#include "attiguard/plan/slew_problem.hpp"

namespace attiguard::plan {

/// One cone in the transcription: the quadratic form M (cone_quadratic.hpp) and, per point, the
/// cosine the point must keep: qᵀ(M − c_p I)q ≥ 0 (docs/slew-planner.md, "Between the nodes").
struct TranscribedCone {
  Eigen::Matrix4d form{Eigen::Matrix4d::Zero()};
  /// c_p for every point p; −∞ where the cone is not imposed (far from the path: the planner
  /// prunes it, docs/slew-planner.md "Speed").
  std::vector<double> cosine_at_point;
};

/// The scaled program (docs/slew-planner.md, "Transcription").
struct TranscriptionSetup {
  Transcription transcription{Transcription::hermite_simpson};
  int intervals{32};
  lie::Mat3 J_scaled{lie::Mat3::Identity()};
  lie::Quat q_start{lie::quat_identity()};   ///< fixed at point 0
  lie::Quat q_target{lie::quat_identity()};  ///< vec(q_targetᶜ ⊗ q_N) = 0 (either sign)
  std::vector<TranscribedCone> cones;
  double torque_limit{1.0};   ///< ‖ū‖ ≤ torque_limit (≤ 1 after a dense check asked for it)
  double max_duration{50.0};  ///< upper bound of T̄
  int max_iterations{800};
  double max_seconds{60.0};
  /// IPOPT's tol and constr_viol_tol (the acceptable levels 1000× and 100× looser); the
  /// screening's coarse solves use a looser one (docs/slew-planner.md, "Speed").
  double tolerance{1e-9};
};

/// Number of transcription points: 2N + 1 (Hermite–Simpson: nodes and midpoints) or N + 1.
[[nodiscard]] int transcription_points(Transcription transcription, int intervals) noexcept;

/// Points z_p = [q, ω̄, ū] and the duration T̄ (scaled units).
struct TranscriptionValues {
  std::vector<PointVector> points;
  double duration{1.0};
  /// IPOPT's multipliers at a solution (bounds z_L, z_U and constraints λ), or empty. A guess
  /// that carries them, for a program of the same structure (a re-solve after a dense check),
  /// warm-starts IPOPT near its barrier parameter's end instead of at 0.1.
  std::vector<double> z_lower, z_upper, lambda;
};

/// What IPOPT returned.
struct TranscriptionResult {
  bool solved{false};       ///< Solve_Succeeded or Solved_To_Acceptable_Level
  std::string status;       ///< IPOPT's return status, by name
  int iterations{0};
  TranscriptionValues values;  ///< the last iterate (the solution when solved)
};

/// Solves the transcribed slew from `guess` (docs/slew-planner.md, "Transcription"). Never
/// throws for a solver failure: `solved` is false and `status` says why. Throws Interrupted
/// when SIGINT/SIGTERM arrived during the solve.
[[nodiscard]] TranscriptionResult solve_transcription(const TranscriptionSetup& setup,
                                                      const TranscriptionValues& guess);

}  // namespace attiguard::plan
