#pragma once
/// @file tube.hpp
/// Sound per-interval enclosures U_i of the reach tube (Algorithm 1, GetReachTube), around a
/// nominal trajectory sampled at sub-step boundaries.
///
/// Per sub-step [s, s+h]:
///  1. A priori enclosure (interval Picard–Lindelöf): a box G ⊂ R³ of ω and a bi-invariant ball
///     of radius ρ_G around R_n(s) such that W_s + [0, h]·X_ω(G) ⊆ G and e_R(s) + h·max_G‖ω‖ ≤ ρ_G.
///     Then every trajectory starting in the set at s stays in G over [s, s+h].
///  2. Deviation bounds z = (d_1, d_2, d_3, e_ω, e_R) from the nominal (deviation.hpp) — |ω_k − ω_n,k| ≤ d_k,
///     ‖ω − ω_n‖ ≤ e_ω, d(R, R_n) ≤ e_R — obey the linear comparison system ż ≤ M z, with M Metzler:
///       ḋ_k ≤ sup B_kk d_k + Σ_{j≠k} sup|B_kj| d_j + ‖row_k A‖ e_R       (interval Jacobians on G)
///       ė_ω ≤ μ₂(B) e_ω + ‖A‖ e_R,   ė_R ≤ e_ω + max_G‖ω‖ e_R
///     (Dini derivatives; the last from the body velocity ω − Eᵀω_n of E = R_nᵀR). Hence
///     z(s+h) ≤ exp(M h) z(s) (Kamke/Metzler comparison), and sup over the sub-step ≤ exp(M⁺h) z(s)
///     with M⁺ = M with negative diagonal entries set to 0.
///  3. The sub-step box: the "tent" bounds of x*, the exact solution from the nominal point at s
///     (from ω_n(s), ω_n(s+h) ± ε and X_ω(G)) ± the sup deviation, intersected with G.
/// The deviations are taken from x*, and ε — a bound on the nominal's integration error over the
/// sub-step, |x*(s+h) − nominal(s+h)| ≤ ε (nominal_error.hpp) — is added at every sub-step end,
/// so the tube, U_i and the ball radii rest on no integration-error allowance.
/// docs/reach.md ("Enclosure U_i", "Nominal error bound") gives the proofs.

#include <algorithm>
#include <limits>
#include <span>
#include <vector>

#include "attiguard/core/errors.hpp"

#include "attiguard/reach/closed_loop.hpp"
#include "attiguard/reach/deviation.hpp"

namespace attiguard::reach {

/// A nominal state at time t.
struct NominalPoint {
  double t{0.0};
  Mat3 R{Mat3::Identity()};
  Vec3 omega{Vec3::Zero()};
};

/// Sound enclosure of every state over [t0, t1].
struct TubeSegment {
  double t0{0.0};
  double t1{0.0};
  AttitudeBall attitude;
  Box3 omega;
  /// Bound on ‖ω‖ over the segment, tighter than the box's corner: max‖ω*‖ over the tent of x*
  /// plus the sup of the Euclidean deviation e_ω (tube.hpp, step 3); +∞ when not computed (the box
  /// then bounds it).
  double omega_norm{std::numeric_limits<double>::infinity()};
  /// min(‖ω‖ bound, the box's norm_max): what the ω-norm safety check uses.
  [[nodiscard]] double omega_norm_bound() const { return std::min(omega_norm, omega.norm_max()); }
};

struct TubeResult {
  std::vector<TubeSegment> segments;  ///< one per sub-step
  Deviation end;                      ///< deviation bounds at the last nominal point
  /// Deviation bounds of the exact trajectory from nominal.front() at the last nominal point:
  /// the nominal's integration error over the whole span.
  Deviation nominal_error;
  Box3 omega_hull;                    ///< hull of the segments' ω boxes
  AttitudeBall attitude_hull;         ///< centred at the first nominal point, contains all
  /// The nominal points the segments run between (segments.size() + 1): the given ones, with
  /// the mid-points of bisected sub-steps inserted (TubeRefinement).
  std::vector<NominalPoint> points;
  int bisections{0};                  ///< sub-steps bisected
};

/// Sub-step bisection (docs/reach.md, "Adaptive steps"): a sub-step whose a priori enclosure
/// diverges or whose nominal error cannot be bounded is split in two at its mid-time, the
/// mid-point simulated from its first point (RKMK4, step ≤ integrator_step), recursively up to
/// max_depth halvings; then the sub-step's error is thrown. max_depth = 0: no bisection.
struct TubeRefinement {
  double integrator_step{0.0};
  int max_depth{0};
};

/// The a priori enclosure of a sub-step diverges (tube.hpp, step 1): the set cannot be carried
/// over it. A NumericalError, so that code which does not handle it stops with exit 3; ConReach
/// turns it into an unproved interval (conreach.hpp).
class EnclosureDiverges : public NumericalError {
 public:
  using NumericalError::NumericalError;
};

/// Whether the nominal's integration error ε enters the tube (docs/reach.md, "Nominal error
/// bound"). Every analysis uses `bounded`; `omitted_unsound` exists only so that a test can show
/// that without ε a crafted tube misses the exact solution (issue 15), and no scenario key sets it.
enum class NominalErrorTerm { bounded, omitted_unsound };

/// Propagates `start` (valid at nominal.front()) along the nominal points (≥ 2, increasing t),
/// bisecting failing sub-steps as `refine` allows. Throws EnclosureDiverges when no a priori
/// enclosure is found (diverging tube), and VerificationFailure when the nominal's integration
/// error cannot be bounded on a sub-step.
[[nodiscard]] TubeResult propagate_tube(const ClosedLoop& loop, std::span<const NominalPoint> nominal,
                                        const Deviation& start,
                                        NominalErrorTerm term = NominalErrorTerm::bounded,
                                        const TubeRefinement& refine = {});

/// exp(M h) for a small square matrix (scaling and squaring, Taylor degree 18).
[[nodiscard]] Eigen::MatrixXd expm(const Eigen::MatrixXd& M);

}  // namespace attiguard::reach
