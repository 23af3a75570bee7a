#include "attiguard/reach/tube.hpp"
#include "attiguard/lie/symmetric_eigen.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>
#include <sstream>

#include "attiguard/core/errors.hpp"
#include "attiguard/reach/lmi_proof.hpp"
#include "attiguard/reach/nominal_error.hpp"
#include "attiguard/reach/simulate.hpp"

namespace attiguard::reach {

Eigen::MatrixXd expm(const Eigen::MatrixXd& M) {
  const double norm = M.cwiseAbs().rowwise().sum().maxCoeff();
  int squarings = 0;
  if (norm > 0.5) squarings = static_cast<int>(std::ceil(std::log2(norm / 0.5)));
  const Eigen::MatrixXd A = M / std::ldexp(1.0, squarings);
  Eigen::MatrixXd term = Eigen::MatrixXd::Identity(M.rows(), M.cols());
  Eigen::MatrixXd sum = term;
  for (int k = 1; k <= 18; ++k) {
    term = term * A / static_cast<double>(k);
    sum += term;
  }
  for (int i = 0; i < squarings; ++i) sum = sum * sum;
  return sum;
}

namespace tube_rounding {

/// nextafter(x, ±∞) without the libm call (scalar_interval.hpp): the tube's exp bound rounds ~10⁴
/// operations per sub-step.
inline double up(double x) { return next_up(x); }
inline double down(double x) { return next_down(x); }
double add_up(double a, double b) { return up(a + b); }
double mul_up(double a, double b) { return up(a * b); }

/// Upper bound of the Frobenius norm of M.
double frobenius_upper(const Mat3& M) {
  double s = 0.0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) s = add_up(s, mul_up(M(i, j), M(i, j)));
  }
  return up(std::sqrt(s));
}

/// Upper bound of λ_max(S) for a symmetric S: λ̃ + δ proved by S − (λ̃ + δ)I ≺ 0 (lmi_proof.hpp),
/// δ growing; Gershgorin's bound if no proof succeeds.
double lambda_max_upper(const Mat3& S) {
  const double lam = lie::lambda_max(S);
  const double scale = std::max(frobenius_upper(S), std::numeric_limits<double>::min());
  for (int i = 0; i < 4; ++i) {
    const double mu = add_up(lam, mul_up(scale, std::ldexp(1.0, -48 + 8 * i)));
    if (std::isfinite(mu) && prove_less(S, mu * Mat3::Identity()).proved) return mu;
  }
  double g = -std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    double r = S(k, k);
    for (int j = 0; j < 3; ++j) {
      if (j != k) r = add_up(r, std::abs(S(k, j)));
    }
    g = std::max(g, r);
  }
  return g;
}

/// Upper bound of sup μ₂(B) = λ_max(½(B + Bᵀ)) over the interval matrix: λ_max of the symmetric
/// part S̃ of the midpoint B_c as computed (plus the rounding of S̃, ≤ 2⁻⁵³|S̃_ij| per entry) plus
/// ‖B − B_c‖₂ ≤ ‖rad‖_F.
double log_norm_upper(const IntervalMat3& B) {
  const Mat3 Bc = B.center();
  const Mat3 S = 0.5 * (Bc + Bc.transpose());
  const double sym_error = add_up(mul_up(frobenius_upper(S), 0x1p-52), 0x1p-1020);
  Mat3 rad;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      rad(i, j) = std::max({0.0, (Interval(B.hi(i, j)) - Interval(Bc(i, j))).hi,
                            (Interval(Bc(i, j)) - Interval(B.lo(i, j))).hi});
    }
  }
  return add_up(add_up(lambda_max_upper(S), sym_error), frobenius_upper(rad));
}

/// ‖P‖_∞ rounded up.
double inf_norm_upper(const Mat5& P) {
  double n = 0.0;
  for (int i = 0; i < 5; ++i) {
    double r = 0.0;
    for (int j = 0; j < 5; ++j) r = add_up(r, std::abs(P(i, j)));
    n = std::max(n, r);
  }
  return n;
}

/// A·B rounded up, for A, B ≥ 0 entrywise.
Mat5 product_upper(const Mat5& A, const Mat5& B) {
  Mat5 C;
  for (int i = 0; i < 5; ++i) {
    for (int j = 0; j < 5; ++j) {
      double s = 0.0;
      for (int l = 0; l < 5; ++l) s = add_up(s, mul_up(A(i, l), B(l, j)));
      C(i, j) = s;
    }
  }
  return C;
}

/// x·2^-q rounded up (exact unless it underflows).
double scale_upper(double x, int q) {
  const double y = std::ldexp(x, -q);
  return std::ldexp(y, q) == x ? y : up(y);
}

/// Σ_{k≤20} N^k/k! + tail, rounded up: an entrywise upper bound of exp(N) for N ≥ 0 with
/// ‖N‖_∞ < 22 (every entry of the tail matrix is at most its ∞-norm).
Mat5 taylor_exp_upper(const Mat5& N) {
  constexpr int K = 20;
  Mat5 term = Mat5::Identity();
  Mat5 sum = Mat5::Identity();
  for (int k = 1; k <= K; ++k) {
    term = product_upper(term, N);
    for (int i = 0; i < 25; ++i) term.data()[i] = up(term.data()[i] / k);
    for (int i = 0; i < 25; ++i) sum.data()[i] = add_up(sum.data()[i], term.data()[i]);
  }
  const double eta = inf_norm_upper(N);
  double t = 1.0;
  for (int k = 1; k <= K + 1; ++k) t = up(mul_up(t, eta) / k);
  const double den = down(1.0 - up(eta / (K + 2)));
  const double tail = den > 0.0 ? up(t / den) : std::numeric_limits<double>::infinity();
  for (int i = 0; i < 25; ++i) sum.data()[i] = add_up(sum.data()[i], tail);
  return sum;
}

}  // namespace tube_rounding

Interval sub_step_duration(double t0, double t1) {
  // rounding site: apriori-box (the duration): TwoSum gives the exact error of t1 − t0.
  const double d = t1 - t0;
  const double bp = d - t1;
  const double ap = d - bp;
  const double err = (t1 - ap) + (-t0 - bp);
  if (err > 0.0) return {d, Interval::up(d)};
  if (err < 0.0) return {Interval::down(d), d};
  return {d, d};
}

double norm_upper(const Vec3& v) {
  using namespace tube_rounding;
  double s = 0.0;
  for (int k = 0; k < 3; ++k) s = add_up(s, mul_up(v(k), v(k)));
  return up(std::sqrt(s));
}

double norm_max_upper(const Box3& b) { return norm_upper(b.abs_max()); }

Box3 inflated_outward(const Box3& b, const Vec3& by) {
  Box3 out;
  for (int k = 0; k < 3; ++k) {
    out.lo(k) = (Interval(b.lo(k)) - Interval(by(k))).lo;
    out.hi(k) = (Interval(b.hi(k)) + Interval(by(k))).hi;
  }
  return out;
}

Box3 apriori_span(const Box3& W, const Box3& F, const Interval& h) {
  // rounding site: apriori-box
  Box3 out;
  for (int k = 0; k < 3; ++k) {
    out.lo(k) = (Interval(W.lo(k)) + Interval(std::min(0.0, (h * Interval(F.lo(k))).lo))).lo;
    out.hi(k) = (Interval(W.hi(k)) + Interval(std::max(0.0, (h * Interval(F.hi(k))).hi))).hi;
  }
  return out;
}

double apriori_attitude_need(double eR, const Interval& h, const Box3& G) {
  // rounding site: apriori-box (the attitude radius)
  return tube_rounding::add_up(eR, tube_rounding::mul_up(h.hi, norm_max_upper(G)));
}

Mat5 comparison_matrix(const IntervalMat3& A, const IntervalMat3& B, const Box3& G) {
  // rounding site: comparison-matrix
  using namespace tube_rounding;
  const Mat3 Aabs = A.abs_max();
  const Mat3 Babs = B.abs_max();
  Mat5 M = Mat5::Zero();
  for (int k = 0; k < 3; ++k) {
    for (int i = 0; i < 3; ++i) M(k, i) = (i == k) ? B.hi(k, k) : Babs(k, i);
    M(k, 4) = norm_upper(Aabs.row(k).transpose());
  }
  M(3, 3) = log_norm_upper(B);
  M(3, 4) = frobenius_upper(Aabs);
  M(4, 3) = 1.0;
  M(4, 4) = norm_max_upper(G);
  return M;
}

Mat5 exp_metzler_upper(const Mat5& M, const Interval& h) {
  // rounding site: comparison-exp
  using namespace tube_rounding;
  Mat5 P;  // ≥ M t entrywise for every t ∈ h, off-diagonal ≥ 0
  for (int i = 0; i < 5; ++i) {
    for (int j = 0; j < 5; ++j) {
      P(i, j) = (Interval(M(i, j)) * h).hi;
      if (i != j) P(i, j) = std::max(P(i, j), 0.0);
    }
  }
  const double norm = inf_norm_upper(P);
  if (!std::isfinite(norm)) return Mat5::Constant(std::numeric_limits<double>::infinity());
  int q = 0;
  while (std::ldexp(norm, -q) > 0.5) ++q;
  for (int i = 0; i < 25; ++i) P.data()[i] = scale_upper(P.data()[i], q);
  double s = 0.0;
  for (int k = 0; k < 5; ++k) s = std::max(s, -P(k, k));
  Mat5 N = P;  // P = N − sI with N ≥ 0
  for (int k = 0; k < 5; ++k) N(k, k) = add_up(P(k, k), s);
  Mat5 E = taylor_exp_upper(N);
  if (s > 0.0) {
    const double f = up(up(std::exp(-s)));  // libm's exp within 1 ulp
    for (int i = 0; i < 25; ++i) E.data()[i] = mul_up(f, E.data()[i]);
  }
  for (int i = 0; i < q; ++i) E = product_upper(E, E);
  return E;
}

Deviation::Vector apply_upper(const Mat5& E, const Deviation::Vector& z, const Deviation::Vector& a) {
  // rounding site: comparison-exp (z(s+h) ≤ exp(Mh) z(s) + ε)
  using namespace tube_rounding;
  Deviation::Vector out;
  for (int i = 0; i < 5; ++i) {
    double s = a(i);
    for (int j = 0; j < 5; ++j) s = add_up(s, mul_up(E(i, j), z(j)));
    out(i) = s;
  }
  return out;
}

double tent_lower(double a, double b, double lo, double hi, const Interval& h) {
  // rounding site: tent-box
  const auto f1 = [&](double t) { return (Interval(a) + Interval(t) * Interval(lo)).lo; };
  const auto f2 = [&](double t) { return (Interval(b) - (h - Interval(t)) * Interval(hi)).lo; };
  // Over [t0, t1] the tent is at least the larger of the two lines' minima (at an end).
  const auto piece = [&](double t0, double t1) {
    return std::max(std::min(f1(t0), f1(t1)), std::min(f2(t0), f2(t1)));
  };
  double ts = 0.0;
  if (hi > lo) {
    ts = (a - b + h.hi * hi) / (hi - lo);
    if (!(ts > 0.0)) ts = 0.0;
    ts = std::min(ts, h.hi);
  }
  return std::min(piece(0.0, ts), piece(ts, h.hi));
}

double tent_upper(double a, double b, double lo, double hi, const Interval& h) {
  return -tent_lower(-a, -b, -hi, -lo, h);
}

double distance_upper(const Mat3& R1, const Mat3& R2) {
  // rounding site: attitude-hull
  using namespace tube_rounding;
  double s = 0.0;
  for (int i = 0; i < 9; ++i) {
    const double d = (Interval(R1.data()[i]) - Interval(R2.data()[i])).mag();
    s = add_up(s, mul_up(d, d));
  }
  const double frob = up(std::sqrt(s));
  const double two_sqrt2_lo = 2.0 * down(std::sqrt(2.0));  // < 2√2 (sqrt correctly rounded)
  const double ratio = up(frob / two_sqrt2_lo);
  if (!(ratio < 1.0)) return up(up(up(std::acos(-1.0))));  // π, libm within 1 ulp
  return 2.0 * up(up(std::asin(ratio)));  // libm's asin within 1 ulp; asin increasing
}

double omega_norm_upper(const Box3& tent, double e_omega_sup) {
  // rounding site: omega-norm-bound
  return tube_rounding::add_up(norm_max_upper(tent), e_omega_sup);
}

namespace {

/// Step 1 of tube.hpp: G ⊇ W + [0, h]·X_ω(G) and ρ_G ≥ e_R + h·max_G‖ω‖, with F = X_ω over
/// (B_I(R_0, ρ_G), G).
struct AprioriEnclosure {
  Box3 F;
  Box3 G;
  double rhoG{0.0};
};

/// The a-priori enclosure of every trajectory from W × B_I(R_0, e_R) over [p0.t, p1.t]
/// (docs/reach.md, "Enclosure U_i", step 1); nothing when the iteration diverges.
std::optional<AprioriEnclosure> a_priori_enclosure(const ClosedLoop& loop, const NominalPoint& p0,
                                                   const NominalPoint& p1, const Box3& W, double eR) {
  const Interval h = sub_step_duration(p0.t, p1.t);
  Box3 F = loop.omega_dot_enclosure({p0.R, eR}, W);
  Box3 G = apriori_span(W, F, h);
  G = G.inflated(0.1 * G.radius() + Vec3::Constant(1e-12));
  double rhoG = (eR + h.hi * G.norm_max()) * 1.1 + 1e-12;
  for (int it = 0; it < 40; ++it) {
    if (!G.finite() || !std::isfinite(rhoG) || rhoG > 1e6) break;
    F = loop.omega_dot_enclosure({p0.R, rhoG}, G);
    // rounding site: apriori-box (the test G ⊇ cand, ρ_G ≥ needR is exact on the bounds)
    const Box3 cand = apriori_span(W, F, h);
    const double needR = apriori_attitude_need(eR, h, G);
    if (G.contains(cand) && needR <= rhoG) return AprioriEnclosure{F, G, rhoG};
    G = G.hull(cand);
    G = G.inflated(0.25 * (cand.radius()) + Vec3::Constant(1e-12));
    rhoG = std::max(rhoG, 1.25 * needR + 1e-12);
  }
  return std::nullopt;
}

/// The Metzler matrix M of the comparison system ż ≤ M z on (B_I(R_0, ρ_G), G) (docs/reach.md,
/// "Enclosure U_i", step 2), rows and columns in the order of Deviation::Vector.
Mat5 comparison_matrix(const ClosedLoop& loop, const Mat3& R0, const AprioriEnclosure& apriori) {
  const AttitudeBall attG{R0, apriori.rhoG};
  return comparison_matrix(loop.A_enclosure(attG, apriori.G), loop.B_enclosure(attG, apriori.G),
                           apriori.G);
}

/// exp(M h) and exp(M⁺ h), M⁺ = M with negative diagonal entries set to 0: the end and the sup
/// over the sub-step of the comparison system.
struct ComparisonFlow {
  Mat5 E;
  Mat5 Eplus;
};

ComparisonFlow comparison_flow(const Mat5& M, const Interval& h) {
  Mat5 Mplus = M;
  for (int k = 0; k < 5; ++k) Mplus(k, k) = std::max(0.0, Mplus(k, k));
  return {exp_metzler_upper(M, h), exp_metzler_upper(Mplus, h)};
}

/// ε of the sub-step: x* (the exact solution from p0, inside G over [s, s+h] since p0 is in the
/// set) ends within ε of p1 (nominal_error.hpp); zero for NominalErrorTerm::omitted_unsound.
/// Nothing (and `why`) when ε cannot be bounded.
std::optional<Deviation> sub_step_error(const PolynomialField& field, const NominalPoint& p0,
                                        const NominalPoint& p1, const AprioriEnclosure& apriori,
                                        NominalErrorTerm term, std::string& why) {
  const std::optional<NominalStepError> step_error = nominal_step_error(
      field, p0.R, p0.omega, p1.R, p1.omega, p1.t - p0.t, apriori.G, apriori.rhoG, why);
  if (!step_error) return std::nullopt;
  return term == NominalErrorTerm::bounded ? step_error->bound : Deviation{};
}

/// Step 3 of tube.hpp: the tent of x* (ω*(s) = ω_0, ω*(s+h) ∈ ω_1 ± ε, slopes in F) ± the sup
/// deviation, intersected with G and with the tent of the whole set.
TubeSegment segment_enclosure(const NominalPoint& p0, const NominalPoint& p1,
                              const AprioriEnclosure& apriori, const Deviation& eps,
                              const Vec3& dev0, const Deviation& z1, const Deviation& zsup) {
  // rounding site: tent-box (end values rounded outward, tent_lower/tent_upper, inflation)
  const Interval h = sub_step_duration(p0.t, p1.t);
  const Box3& F = apriori.F;
  const Box3 end_eps = inflated_outward({p1.omega, p1.omega}, eps.d_omega_b);
  Box3 nom;
  for (int k = 0; k < 3; ++k) {
    nom.lo(k) = tent_lower(p0.omega(k), end_eps.lo(k), F.lo(k), F.hi(k), h);
    nom.hi(k) = tent_upper(p0.omega(k), end_eps.hi(k), F.lo(k), F.hi(k), h);
  }
  const Vec3 devsup = zsup.omega_half_widths();
  // Tent of the whole set: every ω_k(t) is C¹ with derivative in F on G and its values at
  // s and s+h lie in the deviation boxes there (tent_lower/upper are monotone in a and b).
  const Box3 start_box = inflated_outward({p0.omega, p0.omega}, dev0);
  const Box3 end_box = inflated_outward({p1.omega, p1.omega}, z1.omega_half_widths());
  Box3 set_tent;
  for (int k = 0; k < 3; ++k) {
    set_tent.lo(k) = tent_lower(start_box.lo(k), end_box.lo(k), F.lo(k), F.hi(k), h);
    set_tent.hi(k) = tent_upper(start_box.hi(k), end_box.hi(k), F.lo(k), F.hi(k), h);
  }
  TubeSegment seg;
  seg.t0 = p0.t;
  seg.t1 = p1.t;
  seg.omega = inflated_outward(nom, devsup).intersect(apriori.G).intersect(set_tent);
  // ‖ω‖ ≤ ‖ω*(t)‖ + ‖ω − ω*(t)‖ ≤ max over the tent of x* + sup e_ω (deviations are from x*).
  // The factor 1 + 1e-12 and the 1e-12 below predate the outward rounding (which makes them
  // redundant); kept so that the example figures move least.
  seg.omega_norm = omega_norm_upper(nom, zsup.e_omega_b) * (1.0 + 1e-12);
  // rounding site: tent-box (the segment's attitude radius e_R + h·max‖ω*‖, as in step 1)
  seg.attitude = {p0.R, std::min(apriori.rhoG, apriori_attitude_need(zsup.e_R, h, nom) + 1e-12)};
  return seg;
}

/// Adds a segment to the hulls of U_i (attitude hull centred at the first nominal point).
void add_to_hulls(TubeResult& out, const TubeSegment& seg, const Mat3& R_first, bool first) {
  if (first) {
    out.omega_hull = seg.omega;
    out.attitude_hull = {R_first, seg.attitude.radius};
  } else {
    out.omega_hull = out.omega_hull.hull(seg.omega);
    out.attitude_hull.radius = std::max(out.attitude_hull.radius,
                                        tube_rounding::add_up(
                                            distance_upper(R_first, seg.attitude.center),
                                            seg.attitude.radius));
  }
}

/// One sub-step of propagate_tube from the deviation z at p0: its segment and the deviations at
/// p1; nothing when its a priori enclosure diverges or its ε cannot be bounded (`failure`).
struct SubStep {
  TubeSegment seg;
  Deviation z1;
  Deviation e1;
};

std::optional<SubStep> sub_step(const ClosedLoop& loop, const PolynomialField& field,
                                const NominalPoint& p0, const NominalPoint& p1, const Deviation& z,
                                const Deviation& e, NominalErrorTerm term, std::string& failure,
                                bool& verification) {
  const Vec3 dev0 = z.omega_half_widths();
  // rounding site: apriori-box (W_s = ω_n(s) ± d, outward)
  const std::optional<AprioriEnclosure> apriori =
      a_priori_enclosure(loop, p0, p1, inflated_outward({p0.omega, p0.omega}, dev0), z.e_R);
  if (!apriori) {
    std::ostringstream os;
    os << "ConReach tube: no a priori enclosure over [" << p0.t << ", " << p1.t
       << "] s (the enclosure diverges; use more sub-steps, a smaller initial set or a shorter "
          "horizon)";
    failure = os.str();
    verification = false;
    return std::nullopt;
  }
  std::string why;
  const std::optional<Deviation> eps = sub_step_error(field, p0, p1, *apriori, term, why);
  if (!eps) {
    std::ostringstream os;
    os << "ConReach tube: the nominal's integration error cannot be bounded over [" << p0.t
       << ", " << p1.t << "] s (" << why << "): cannot prove; use more sub-steps or a smaller "
       << "integrator_step";
    failure = os.str();
    verification = true;
    return std::nullopt;
  }
  const ComparisonFlow flow =
      comparison_flow(comparison_matrix(loop, p0.R, *apriori), sub_step_duration(p0.t, p1.t));
  // Deviations from x*: z(s+h) ≤ exp(Mh) z(s), sup over the sub-step ≤ exp(M⁺h) z(s); from p1
  // add eps (triangle inequality, componentwise and in d), all rounded up (apply_upper). The
  // factor and 1e-15 once covered the rounding of the 5×5 products; now redundant, kept so that
  // the example figures move least.
  const Deviation::Vector z0 = z.vector();
  const Deviation::Vector none = Deviation::Vector::Zero();
  SubStep out;
  out.z1 = Deviation::from_vector(apply_upper(flow.E, z0, eps->vector()) * (1.0 + 1e-12) +
                                  Deviation::Vector::Constant(1e-15));
  const Deviation zsup = Deviation::from_vector(apply_upper(flow.Eplus, z0, none) * (1.0 + 1e-12) +
                                                Deviation::Vector::Constant(1e-15));
  out.e1 = Deviation::from_vector(apply_upper(flow.E, e.vector(), eps->vector()) * (1.0 + 1e-12));
  out.seg = segment_enclosure(p0, p1, *apriori, *eps, dev0, out.z1, zsup);
  // Deviation at p1; the ω part can also be read off G.
  out.z1.e_R = std::min(out.z1.e_R, apriori->rhoG);
  return out;
}

/// The nominal point at the mid-time of [p0, p1], simulated from p0 (RKMK4, step ≤ h).
NominalPoint mid_point(const ClosedLoop& loop, const NominalPoint& p0, const NominalPoint& p1, double h) {
  const double tm = 0.5 * (p0.t + p1.t);
  NominalPoint mid{tm, p0.R, p0.omega};
  const std::vector<double> stop{tm};
  simulate_from(loop, p0.t, p0.R, p0.omega, stop, std::min(h, tm - p0.t),
                [&](std::size_t, const Mat3& R, const Vec3& w) {
                  mid.R = R;
                  mid.omega = w;
                });
  if (!mid.R.allFinite() || !mid.omega.allFinite()) {
    throw NumericalError("ConReach tube: the nominal is not finite at a bisected sub-step");
  }
  return mid;
}

}  // namespace

TubeResult propagate_tube(const ClosedLoop& loop, std::span<const NominalPoint> nominal,
                          const Deviation& start, NominalErrorTerm term, const TubeRefinement& refine) {
  if (nominal.size() < 2) throw NumericalError("ConReach tube: needs at least two nominal points");
  TubeResult out;
  Deviation z = Deviation::from_vector(start.vector().cwiseMax(0.0));
  Deviation e;  // the exact trajectory from nominal.front(): its deviation
  const PolynomialField field = loop.polynomial_field();
  out.points.push_back(nominal.front());
  for (std::size_t j = 0; j + 1 < nominal.size(); ++j) {
    // Pending sub-steps of [nominal[j], nominal[j+1]], last first, with their bisection depth.
    std::vector<std::pair<NominalPoint, int>> pending{{nominal[j + 1], 0}};
    while (!pending.empty()) {
      const NominalPoint p0 = out.points.back();
      const auto [p1, depth] = pending.back();
      std::string failure;
      bool verification = false;
      std::optional<SubStep> done = sub_step(loop, field, p0, p1, z, e, term, failure, verification);
      if (!done) {
        if (depth >= refine.max_depth || !(refine.integrator_step > 0.0)) {
          if (verification) throw VerificationFailure(failure);
          throw EnclosureDiverges(failure);
        }
        pending.back().second = depth + 1;
        pending.emplace_back(mid_point(loop, p0, p1, refine.integrator_step), depth + 1);
        ++out.bisections;
        continue;
      }
      pending.pop_back();
      add_to_hulls(out, done->seg, nominal.front().R, out.segments.empty());
      out.segments.push_back(done->seg);
      out.points.push_back(p1);
      z = done->z1;
      e = done->e1;
    }
  }
  out.end = z;
  out.nominal_error = e;
  return out;
}

}  // namespace attiguard::reach
