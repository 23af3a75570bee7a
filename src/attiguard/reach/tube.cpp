#include "attiguard/reach/tube.hpp"
#include "attiguard/lie/symmetric_eigen.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>
#include <sstream>

#include "attiguard/core/errors.hpp"
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

namespace {

using Mat5 = Eigen::Matrix<double, 5, 5>;

/// min over t ∈ [0, h] of max(a + t·lo, b − (h − t)·hi): a lower bound of a C¹ function with
/// values a at 0, b at h and derivative in [lo, hi].
double tent_min(double a, double b, double lo, double hi, double h) {
  auto L = [&](double t) { return std::max(a + t * lo, b - (h - t) * hi); };
  double m = std::min(L(0.0), L(h));
  if (hi > lo) {
    const double ts = (a - b + h * hi) / (hi - lo);
    if (ts > 0.0 && ts < h) m = std::min(m, L(ts));
  }
  return m;
}
/// max over t ∈ [0, h] of min(a + t·hi, b − (h − t)·lo).
double tent_max(double a, double b, double lo, double hi, double h) {
  return -tent_min(-a, -b, -hi, -lo, h);
}

Box3 span_box(const Box3& W, const Box3& F, double h) {
  return {W.lo + (h * F.lo).cwiseMin(0.0), W.hi + (h * F.hi).cwiseMax(0.0)};
}

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
  const double h = p1.t - p0.t;
  Box3 F = loop.omega_dot_enclosure({p0.R, eR}, W);
  Box3 G = span_box(W, F, h);
  G = G.inflated(0.1 * G.radius() + Vec3::Constant(1e-12));
  double rhoG = (eR + h * G.norm_max()) * 1.1 + 1e-12;
  for (int it = 0; it < 40; ++it) {
    if (!G.finite() || !std::isfinite(rhoG) || rhoG > 1e6) break;
    F = loop.omega_dot_enclosure({p0.R, rhoG}, G);
    const Box3 cand = span_box(W, F, h);
    const double needR = eR + h * G.norm_max();
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
  const IntervalMat3 Aenc = loop.A_enclosure(attG, apriori.G);
  const IntervalMat3 Benc = loop.B_enclosure(attG, apriori.G);
  const Mat3 Aabs = Aenc.abs_max();
  const Mat3 Babs = Benc.abs_max();
  Mat5 M = Mat5::Zero();
  for (int k = 0; k < 3; ++k) {
    for (int i = 0; i < 3; ++i) M(k, i) = (i == k) ? Benc.hi(k, k) : Babs(k, i);
    M(k, 4) = Aabs.row(k).norm();
  }
  const Mat3 Bc = Benc.center();
  M(3, 3) = lie::lambda_max(Bc) + Benc.radius().norm();
  M(3, 4) = Aabs.norm();
  M(4, 3) = 1.0;
  M(4, 4) = apriori.G.norm_max();
  return M;
}

/// exp(M h) and exp(M⁺ h), M⁺ = M with negative diagonal entries set to 0: the end and the sup
/// over the sub-step of the comparison system.
struct ComparisonFlow {
  Mat5 E;
  Mat5 Eplus;
};

ComparisonFlow comparison_flow(const Mat5& M, double h) {
  Mat5 Mplus = M;
  for (int k = 0; k < 5; ++k) Mplus(k, k) = std::max(0.0, Mplus(k, k));
  return {expm(M * h), expm(Mplus * h)};
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
  const double h = p1.t - p0.t;
  const Box3& F = apriori.F;
  Box3 nom;
  for (int k = 0; k < 3; ++k) {
    nom.lo(k) = tent_min(p0.omega(k), p1.omega(k) - eps.d_omega_b(k), F.lo(k), F.hi(k), h);
    nom.hi(k) = tent_max(p0.omega(k), p1.omega(k) + eps.d_omega_b(k), F.lo(k), F.hi(k), h);
  }
  const Vec3 devsup = zsup.omega_half_widths();
  // Tent of the whole set: every ω_k(t) is C¹ with derivative in F on G and its values at
  // s and s+h lie in the deviation boxes there (tent_min/max are monotone in a and b).
  const Vec3 dev1 = z1.omega_half_widths();
  Box3 set_tent;
  for (int k = 0; k < 3; ++k) {
    set_tent.lo(k) = tent_min(p0.omega(k) - dev0(k), p1.omega(k) - dev1(k), F.lo(k), F.hi(k), h);
    set_tent.hi(k) = tent_max(p0.omega(k) + dev0(k), p1.omega(k) + dev1(k), F.lo(k), F.hi(k), h);
  }
  TubeSegment seg;
  seg.t0 = p0.t;
  seg.t1 = p1.t;
  seg.omega = nom.inflated(devsup).intersect(apriori.G).intersect(set_tent);
  // ‖ω‖ ≤ ‖ω*(t)‖ + ‖ω − ω*(t)‖ ≤ max over the tent of x* + sup e_ω (deviations are from x*).
  seg.omega_norm = (nom.norm_max() + zsup.e_omega_b) * (1.0 + 1e-12);
  seg.attitude = {p0.R, std::min(apriori.rhoG, zsup.e_R + h * nom.norm_max() + 1e-12)};
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
                                        lie::distance(R_first, seg.attitude.center) + seg.attitude.radius);
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
  const std::optional<AprioriEnclosure> apriori =
      a_priori_enclosure(loop, p0, p1, Box3::around(p0.omega, dev0), z.e_R);
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
  const ComparisonFlow flow = comparison_flow(comparison_matrix(loop, p0.R, *apriori), p1.t - p0.t);
  // Deviations from x*: z(s+h) ≤ exp(Mh) z(s), sup over the sub-step ≤ exp(M⁺h) z(s); from p1
  // add eps (triangle inequality, componentwise and in d). The factor and 1e-15 cover the
  // rounding of the 5×5 products.
  const Deviation::Vector z0 = z.vector();
  SubStep out;
  out.z1 = Deviation::from_vector(((flow.E * z0).cwiseMax(0.0) + eps->vector()) * (1.0 + 1e-12) +
                                  Deviation::Vector::Constant(1e-15));
  const Deviation zsup = Deviation::from_vector((flow.Eplus * z0).cwiseMax(0.0) * (1.0 + 1e-12) +
                                                Deviation::Vector::Constant(1e-15));
  out.e1 = Deviation::from_vector(((flow.E * e.vector()).cwiseMax(0.0) + eps->vector()) * (1.0 + 1e-12));
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
