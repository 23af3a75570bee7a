#pragma once
/// @file conreach.hpp
/// The ConReach loop [ConReach Alg. 1]: metric balls
/// B_{Q_i×P_i}((R_i, ω_i), r_i) along a nominal simulation, r_{i+1} = r_i e^{c_{i+1}(t_{i+1}−t_i)}
/// + the bound of the nominal's integration error over the step (tube.hpp), with (c, Q, P) per step from the SDP [ConReach eq. (20)]
/// over the enclosure U_i of tube.hpp, chosen either by the paper's line search or by
/// minimising the bi-invariant enclosure of the resulting ball.

#include <functional>
#include <string>
#include <vector>

#include "attiguard/reach/closed_loop.hpp"
#include "attiguard/reach/contraction_sdp.hpp"
#include "attiguard/reach/simulate.hpp"
#include "attiguard/reach/tube.hpp"

namespace attiguard::reach {

/// The initial set B_I(R0, attitude_radius) × B_I(ω0, omega_radius) (bi-invariant and
/// Euclidean balls, paper Sec. 6).
struct InitialSet {
  Mat3 R0{Mat3::Identity()};
  double attitude_radius{0.0};
  Vec3 omega0{Vec3::Zero()};
  double omega_radius{0.0};
  /// P_0 of Algorithm 1 (SPD); the covering ball is B_{I×P_0}((R0, ω0), √(a² + λ_max(P_0) b²)).
  Mat3 P0{Mat3::Identity()};
};

/// How the contraction rate of each step is chosen.
struct ReachStep;

enum class RateMode {
  line_search,    ///< Algorithm 1 as the authors run it (docs/errata.md, ConReach 1)
  min_enclosure,  ///< the (c, Q, P) giving the smallest bi-invariant enclosure radius
};

/// The metric family of the balls (docs/reach.md, "Coupled metrics").
enum class MetricKind {
  product,  ///< G_Q × G_P (the paper, Def. 2): S = 0
  coupled,  ///< M = [[Q, S], [Sᵀ, P]]: attitude–ω coupling, contracting for damped loops
};

/// How each step's metric is certified (docs/reach.md, "Rigour").
enum class Rigour {
  rigorous,  ///< interval proof of the LMI, M ≻ 0 and M ⪯ M_i (lmi_proof.hpp); unprovable: cannot_prove
  floating,  ///< double-precision eigenvalue certification only ("float", for speed comparisons)
};

struct ConReachSettings {
  MetricKind metric{MetricKind::product};
  Rigour rigour{Rigour::rigorous};
  double horizon{4.0};            ///< T [s]
  int steps{40};                  ///< N
  RateMode mode{RateMode::line_search};
  int line_search_steps{3};       ///< N_s: rates c_max, c_max − δ, …, c_max − (N_s − 1)δ
  double rate_step{0.01};         ///< δ [1/s]
  double min_diagonal{0.01};      ///< line search stops when a diagonal entry of Q or P is below
  int min_enclosure_candidates{30};  ///< most rates tried by min_enclosure (step δ from c_max; stops after 2 worse)
  int substeps{10};               ///< sub-steps of each [t_i, t_{i+1}] for the tube
  double integrator_step{1e-3};   ///< RKMK4 step of the nominal [s]
  /// For closed loops whose LMI depends on R: Q ⪰ ratio·λ_min(Q_i)·I in the SDP, so that the
  /// G_Q-geodesics of the ball stay in the attitude ball of radius r_i/√(ratio·λ_min(Q_i)).
  double attitude_floor_ratio{0.5};
  /// The per-step SDP's settings (the dense solver first, CSDP when it does not solve;
  /// `sdp.sdp.solver = SdpSolverKind::csdp` for CSDP alone; issue 48, docs/reach.md "Dense SDP
  /// solver").
  MetricSdpSettings sdp;
  /// Step lengths chosen by the analysis (docs/reach.md, "Adaptive steps"); `steps` is then
  /// unused and `integrator_step` ≤ 0 means "derived from the loop".
  bool adaptive{false};
  int max_bisections{6};          ///< halvings of a sub-step whose enclosure or ε fails
  int max_adaptive_steps{2000};   ///< adaptive: most steps of one cell (work bound)
  /// Optional: called after every step; a non-empty reason ends the analysis there (complete =
  /// false, stop time = the `t` it sets). The automatic splitting stops a cell at its first
  /// segment that cannot prove the safety specification (auto_split.hpp).
  std::function<std::string(const ReachStep&, double& t)> step_check;
};

/// One rate tried at one step.
struct RateTrial {
  double c{0.0};
  bool feasible{false};
  double enclosure_radius{0.0};  ///< r_{i+1}/√min(λ_min Q, λ_min P) when feasible
};

/// Step i of Algorithm 1: from the ball at t_i to the ball at t_{i+1}.
struct ReachStep {
  int index{0};
  double t0{0.0};
  double t1{0.0};
  Box3 omega_box;                 ///< U_i, ω part (the LMI's search region)
  AttitudeBall attitude_box;      ///< U_i, attitude part
  std::vector<TubeSegment> state_tube;  ///< enclosure of the reachable states over [t_i, t_{i+1}]
  double c_identity{0.0};         ///< c_max: smallest feasible rate with Q = P = I
  double c{0.0};                  ///< c_{i+1}
  Mat3 Q{Mat3::Identity()};       ///< Q_{i+1}
  Mat3 P{Mat3::Identity()};       ///< P_{i+1}
  Mat3 S{Mat3::Zero()};           ///< S_{i+1} (coupled metric; 0 for the product metric)
  double r{0.0};                  ///< r_{i+1}
  Mat3 R{Mat3::Identity()};       ///< nominal R_{i+1}
  Vec3 omega{Vec3::Zero()};       ///< nominal ω_{i+1}
  double attitude_radius{0.0};    ///< r_{i+1}/√λ_min(Q − SP⁻¹Sᵀ): bi-invariant attitude enclosure
  Vec3 omega_half_widths{Vec3::Zero()};  ///< half-widths of the box around the ball's ω projection
  double numerical_allowance{0.0};  ///< added to r: the nominal's error bound in G_{Q×P}
  double nominal_error_R{0.0};      ///< bound on d(R*(t_{i+1}), R_{i+1}) (nominal's error)
  double nominal_error_omega{0.0};  ///< bound on ‖ω*(t_{i+1}) − ω_{i+1}‖
  bool lmi_exact{false};
  double lmi_rho{0.0};
  bool fallback{false};           ///< no SDP accepted: Q = P = sI at c_max
  bool proved_rigorously{false};  ///< the step's metric was proved in interval arithmetic
  [[nodiscard]] StateMetric metric() const { return {Q, S, P}; }
  int sdp_solves{0};
  std::vector<RateTrial> trials;
};

struct ReachResult {
  InitialSet initial;
  Mat3 Q0{Mat3::Identity()};
  Mat3 P0{Mat3::Identity()};
  Mat3 S0{Mat3::Zero()};  ///< coupled metric: the initial ball is B_{M_1}((R0, ω0), r0)
  double r0{0.0};
  std::vector<ReachStep> steps;
  std::vector<NominalPoint> nominal;  ///< at every sub-step boundary (bisected ones included)
  int sdp_solves{0};
  double wall_time_s{0.0};
  /// False when the analysis stopped before the horizon: a sub-step's enclosure diverged or its
  /// nominal error or a step's metric could not be proved, at the shortest step allowed.
  bool complete{true};
  double stop_time{-1.0};   ///< start of the interval that could not be carried (−1: complete)
  std::string stop_reason;  ///< why
  int bisections{0};        ///< sub-steps bisected in the state tube
  int retries{0};           ///< adaptive: steps redone at half length
};

/// Runs ConReach. Throws InputError for invalid settings and NumericalError for numerical
/// failure (NaN, non-finite nominal). An interval that cannot be carried — the tube's a priori
/// enclosure diverges, the nominal's error or (rigorous mode) every metric of the step cannot be
/// proved — ends the analysis there: the result is returned with complete = false, the steps
/// before it and the reason (docs/reach.md, "Adaptive steps").
[[nodiscard]] ReachResult run_conreach(const ClosedLoop& loop, const InitialSet& initial,
                                       const ConReachSettings& settings);

/// The loop's rate scale λ [1/s] over the initial set: max(√‖A‖, ‖B‖, max‖ω‖) of the LMI's
/// enclosures (closed_loop.hpp) on B_I(R0, a) × B(ω0, b); the adaptive first step is 0.3/λ
/// (docs/reach.md, "Adaptive steps").
[[nodiscard]] double loop_rate_scale(const ClosedLoop& loop, const InitialSet& initial);

}  // namespace attiguard::reach
