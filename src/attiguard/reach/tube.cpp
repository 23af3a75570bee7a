#include "attiguard/reach/tube.hpp"
#include "attiguard/lie/symmetric_eigen.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "attiguard/core/errors.hpp"
#include "attiguard/reach/nominal_error.hpp"

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

}  // namespace

TubeResult propagate_tube(const ClosedLoop& loop, std::span<const NominalPoint> nominal,
                          const Deviation& start, NominalErrorTerm term) {
  if (nominal.size() < 2) throw NumericalError("ConReach tube: needs at least two nominal points");
  TubeResult out;
  Deviation z = start.cwiseMax(0.0);
  Deviation e = Deviation::Zero();  // the exact trajectory from nominal.front(): its deviation
  const PolynomialField field = loop.polynomial_field();
  bool first = true;
  for (std::size_t j = 0; j + 1 < nominal.size(); ++j) {
    const NominalPoint& p0 = nominal[j];
    const NominalPoint& p1 = nominal[j + 1];
    const double h = p1.t - p0.t;
    const Vec3 dev0 = z.head<3>().cwiseMin(z(3));
    const Box3 W = Box3::around(p0.omega, dev0);
    const double eR = z(4);

    // 1. A priori enclosure.
    Box3 F = loop.omega_dot_enclosure({p0.R, eR}, W);
    Box3 G = span_box(W, F, h);
    G = G.inflated(0.1 * G.radius() + Vec3::Constant(1e-12));
    double rhoG = (eR + h * G.norm_max()) * 1.1 + 1e-12;
    bool ok = false;
    for (int it = 0; it < 40 && !ok; ++it) {
      if (!G.finite() || !std::isfinite(rhoG) || rhoG > 1e6) break;
      F = loop.omega_dot_enclosure({p0.R, rhoG}, G);
      const Box3 cand = span_box(W, F, h);
      const double needR = eR + h * G.norm_max();
      if (G.contains(cand) && needR <= rhoG) {
        ok = true;
      } else {
        G = G.hull(cand);
        G = G.inflated(0.25 * (cand.radius()) + Vec3::Constant(1e-12));
        rhoG = std::max(rhoG, 1.25 * needR + 1e-12);
      }
    }
    if (!ok) {
      std::ostringstream os;
      os << "ConReach tube: no a priori enclosure over [" << p0.t << ", " << p1.t
         << "] s (the enclosure diverges; use more sub-steps, a smaller initial set or a shorter "
            "horizon)";
      throw NumericalError(os.str());
    }

    // 2. Comparison system on G.
    const AttitudeBall attG{p0.R, rhoG};
    const IntervalMat3 Aenc = loop.A_enclosure(attG, G);
    const IntervalMat3 Benc = loop.B_enclosure(attG, G);
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
    M(4, 4) = G.norm_max();
    Mat5 Mplus = M;
    for (int k = 0; k < 5; ++k) Mplus(k, k) = std::max(0.0, Mplus(k, k));
    const Mat5 E = expm(M * h);
    const Mat5 Eplus = expm(Mplus * h);

    // The nominal's integration error over the sub-step: x* (the exact solution from p0, inside
    // G over [s, s+h] since p0 is in the set) ends within eps of p1 (nominal_error.hpp).
    std::string why;
    const std::optional<NominalStepError> step_error =
        nominal_step_error(field, p0.R, p0.omega, p1.R, p1.omega, h, G, rhoG, why);
    if (!step_error) {
      std::ostringstream os;
      os << "ConReach tube: the nominal's integration error cannot be bounded over [" << p0.t
         << ", " << p1.t << "] s (" << why << "): cannot prove; use more sub-steps or a smaller "
         << "integrator_step";
      throw VerificationFailure(os.str());
    }
    const Deviation eps = term == NominalErrorTerm::bounded ? step_error->bound : Deviation::Zero();
    // Deviations from x*: z(s+h) ≤ exp(Mh) z(s), sup over the sub-step ≤ exp(M⁺h) z(s); from p1
    // add eps (triangle inequality, componentwise and in d). The factor and 1e-15 cover the
    // rounding of the 5×5 products.
    Deviation z1 = ((E * z).cwiseMax(0.0) + eps) * (1.0 + 1e-12) + Deviation::Constant(1e-15);
    const Deviation zsup = (Eplus * z).cwiseMax(0.0) * (1.0 + 1e-12) + Deviation::Constant(1e-15);
    e = ((E * e).cwiseMax(0.0) + eps) * (1.0 + 1e-12);

    // 3. Segment enclosure: the tent of x* (ω*(s) = ω_0, ω*(s+h) ∈ ω_1 ± eps, slopes in F)
    // ± sup deviation, intersected with G.
    Box3 nom;
    for (int k = 0; k < 3; ++k) {
      nom.lo(k) = tent_min(p0.omega(k), p1.omega(k) - eps(k), F.lo(k), F.hi(k), h);
      nom.hi(k) = tent_max(p0.omega(k), p1.omega(k) + eps(k), F.lo(k), F.hi(k), h);
    }
    const Vec3 devsup = zsup.head<3>().cwiseMin(zsup(3));
    // Tent of the whole set: every ω_k(t) is C¹ with derivative in F on G and its values at
    // s and s+h lie in the deviation boxes there (tent_min/max are monotone in a and b).
    const Vec3 dev1 = z1.head<3>().cwiseMin(z1(3));
    Box3 set_tent;
    for (int k = 0; k < 3; ++k) {
      set_tent.lo(k) = tent_min(p0.omega(k) - dev0(k), p1.omega(k) - dev1(k), F.lo(k), F.hi(k), h);
      set_tent.hi(k) = tent_max(p0.omega(k) + dev0(k), p1.omega(k) + dev1(k), F.lo(k), F.hi(k), h);
    }
    TubeSegment seg;
    seg.t0 = p0.t;
    seg.t1 = p1.t;
    seg.omega = nom.inflated(devsup).intersect(G).intersect(set_tent);
    seg.attitude = {p0.R, std::min(rhoG, zsup(4) + h * nom.norm_max() + 1e-12)};
    out.segments.push_back(seg);

    if (first) {
      out.omega_hull = seg.omega;
      out.attitude_hull = {nominal.front().R, seg.attitude.radius};
      first = false;
    } else {
      out.omega_hull = out.omega_hull.hull(seg.omega);
      out.attitude_hull.radius =
          std::max(out.attitude_hull.radius,
                   lie::distance(nominal.front().R, seg.attitude.center) + seg.attitude.radius);
    }
    // Deviation at p1; the ω part can also be read off G.
    z1(4) = std::min(z1(4), rhoG);
    z = z1;
  }
  out.end = z;
  out.nominal_error = e;
  return out;
}

}  // namespace attiguard::reach
