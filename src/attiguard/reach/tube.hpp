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
/// Every number of steps 1–3 is computed with outward rounding (docs/reach.md, "Rounding
/// sites": apriori-box, comparison-matrix, comparison-exp, tent-box, omega-norm-bound,
/// attitude-hull); the
/// functions below the propagation are those sites.

#include <algorithm>
#include <limits>
#include <span>
#include <vector>

#include "attiguard/core/errors.hpp"

#include "attiguard/reach/closed_loop.hpp"
#include "attiguard/reach/deviation.hpp"
#include "attiguard/reach/scalar_interval.hpp"

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

/// exp(M h) for a small square matrix (scaling and squaring, Taylor degree 18), in
/// round-to-nearest: an approximation, not a bound (the tube uses exp_metzler_upper).
[[nodiscard]] Eigen::MatrixXd expm(const Eigen::MatrixXd& M);

// ---- The tube's rounding sites (docs/reach.md, "Rounding sites"). Each returns a bound for the
// exact real result of its formula on the floating-point inputs, computed with outward rounding
// (scalar_interval.hpp: every operation widened by one ulp; sqrt correctly rounded).

/// The comparison system's 5×5 matrices (rows and columns in the order of Deviation::Vector).
using Mat5 = Eigen::Matrix<double, 5, 5>;

/// The duration p1.t − p0.t of a sub-step as an interval containing the exact difference
/// (docs/reach.md, "Rounding sites"; the floating-point subtraction may round).
[[nodiscard]] Interval sub_step_duration(double t0, double t1);

/// An upper bound of the Euclidean norm ‖v‖ (docs/reach.md, "Rounding sites": squares and their
/// sum rounded up, then the correctly rounded sqrt rounded up).
[[nodiscard]] double norm_upper(const Vec3& v);

/// An upper bound of max over the box of ‖ω‖ (Box3::norm_max with outward rounding; docs/reach.md,
/// "Rounding sites").
[[nodiscard]] double norm_max_upper(const Box3& b);

/// The box b inflated by `by` ≥ 0 on each side, lower ends rounded down and upper ends up
/// (docs/reach.md, "Enclosure U_i", steps 1 and 3: W_s = ω_n ± d and the tent ± sup deviation).
[[nodiscard]] Box3 inflated_outward(const Box3& b, const Vec3& by);

/// W + [0, h]·F of the a priori enclosure (docs/reach.md, "Enclosure U_i", step 1), outward
/// rounded: contains w + t·f for every w ∈ W, f ∈ F and t ∈ [0, h.hi].
[[nodiscard]] Box3 apriori_span(const Box3& W, const Box3& F, const Interval& h);

/// e_R + h·max_G‖ω‖ rounded up: the attitude radius ρ_G must reach for G to be an a priori
/// enclosure (docs/reach.md, "Enclosure U_i", step 1), for every duration in h.
[[nodiscard]] double apriori_attitude_need(double eR, const Interval& h, const Box3& G);

/// The Metzler matrix M of the comparison system ż ≤ M z (docs/reach.md, "Enclosure U_i",
/// step 2) from interval enclosures A, B of the Jacobians and the a priori ω box G; each entry
/// an upper bound of its formula: sup B_kk, sup|B_kj|, ‖row_k |A|‖, μ₂(B) ≤ λ_max(Sym B_c) +
/// ‖rad B‖_F (λ_max proved by lmi_proof.hpp's congruence), ‖|A|‖_F, 1, max_G‖ω‖.
[[nodiscard]] Mat5 comparison_matrix(const IntervalMat3& A, const IntervalMat3& B, const Box3& G);

/// An entrywise upper bound of exp(M t) for every t ∈ h, M Metzler (docs/reach.md, "Enclosure
/// U_i", step 2): with P ≥ M t entrywise (rounded up) scaled by 2^-q, P = N − sI with N ≥ 0 and
/// s ≥ 0, exp(P) = e^{−s} exp(N) ≤ e^{−s}(Σ_{k≤20} N^k/k! + tail), all in upward rounding (every
/// term nonnegative), the tail ‖N‖^21/21!·1/(1 − ‖N‖/22) added to every entry, e^{−s} widened
/// by 2 ulps (libm's exp within 1 ulp), then squared q times (monotone on nonnegative matrices).
[[nodiscard]] Mat5 exp_metzler_upper(const Mat5& M, const Interval& h);

/// E z + a rounded up, for E, z, a ≥ 0 entrywise (docs/reach.md, "Enclosure U_i", step 2, and
/// "Nominal error bound": z(s+h) ≤ exp(Mh) z(s) + ε).
[[nodiscard]] Deviation::Vector apply_upper(const Mat5& E, const Deviation::Vector& z,
                                            const Deviation::Vector& a);

/// A lower bound of min over t ∈ [0, h] of max(a + t·lo, b − (h − t)·hi) for every duration h
/// in `h`: the lower end of the tent of a C¹ function with values a at 0, b at h and derivative
/// in [lo, hi] (docs/reach.md, "Enclosure U_i", step 3). Split at the lines' crossing t_s: on
/// [0, t_s] and [t_s, h] each line is bounded below by its smaller end value (rounded down),
/// so the result holds for any t_s, and the floating-point t_s only costs tightness.
[[nodiscard]] double tent_lower(double a, double b, double lo, double hi, const Interval& h);
/// The upper end: an upper bound of max over t of min(a + t·hi, b − (h − t)·lo) (−tent_lower of
/// the negated data; docs/reach.md, "Enclosure U_i", step 3).
[[nodiscard]] double tent_upper(double a, double b, double lo, double hi, const Interval& h);

/// An upper bound of the bi-invariant distance d(R1, R2) = θ of two rotations, with the
/// floating-point matrices taken as exact rotations: ‖R1 − R2‖_F = 2√2 sin(θ/2), so θ =
/// 2 asin(‖R1 − R2‖_F / 2√2), the norm rounded up and asin widened by 2 ulps (libm within
/// 1 ulp); π when the ratio reaches 1. Used for the hull of the segments' attitude balls around
/// the first nominal point (TubeResult::attitude_hull; docs/reach.md, "Rounding sites").
[[nodiscard]] double distance_upper(const Mat3& R1, const Mat3& R2);

/// Bound on ‖ω‖ over a segment (TubeSegment::omega_norm; docs/reach.md, "Enclosure U_i",
/// step 3): max‖ω*‖ over the tent box of x* plus the sup of e_ω, rounded up.
[[nodiscard]] double omega_norm_upper(const Box3& tent, double e_omega_sup);

}  // namespace attiguard::reach
