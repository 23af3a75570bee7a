#include "attiguard/reach/proved_radii.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "attiguard/reach/lmi_proof.hpp"
#include "attiguard/reach/scalar_interval.hpp"

namespace attiguard::reach {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
/// Relative widenings tried before a proof is given up: 1e-12, 1e-10, …, 1e-4.
constexpr int kAttempts = 5;
double widening(int attempt) { return std::pow(10.0, -12.0 + 2.0 * attempt); }

double radii_down(double x) { return Interval::down(x); }
double radii_up(double x) { return Interval::up(x); }

Mat6 block_selector(StateBlock block, double value) {
  Mat6 E = Mat6::Zero();
  const int k = block == StateBlock::attitude ? 0 : 3;
  E.block<3, 3>(k, k) = value * Mat3::Identity();
  return E;
}

double max_eigenvalue(const Mat6& X) {
  const Eigen::SelfAdjointEigenSolver<Mat6> es(0.5 * (X + X.transpose()), Eigen::EigenvaluesOnly);
  return es.eigenvalues()(5);
}

/// The double-precision λ_max of W^{-1/2} M W^{-1/2}, W = diag(w_R I, w_ω I).
double weighted_max(const Mat6& M, double w_r, double w_w) {
  Eigen::Matrix<double, 6, 1> d;
  d << Vec3::Constant(1.0 / std::sqrt(w_r)), Vec3::Constant(1.0 / std::sqrt(w_w));
  return max_eigenvalue(d.asDiagonal() * M * d.asDiagonal());
}

/// λ proved with M ⪯ λ·diag(w_R I, w_ω I), starting from lam_f = weighted_max(M, w_R, w_ω);
/// +∞ when no widening proves it.
double proved_weighted_max(const Mat6& M, double w_r, double w_w, double lam_f) {
  if (!(lam_f > 0.0) || !std::isfinite(lam_f)) return kInf;
  for (int attempt = 0; attempt < kAttempts; ++attempt) {
    const double lam = lam_f * (1.0 + widening(attempt));
    Mat6 W = Mat6::Zero();
    W.topLeftCorner<3, 3>() = (lam * w_r) * Mat3::Identity();
    W.bottomRightCorner<3, 3>() = (lam * w_w) * Mat3::Identity();
    // The proof is about the floats lam·w as stored: M ≺ diag(fl(λw_R), fl(λw_ω)); so
    // zᵀMz ≤ fl(λw_R)a² + fl(λw_ω)b², bounded above in the caller's weights by dividing back.
    if (prove_less(M, W).proved) {
      const double scale_r = radii_up(W(0, 0) / w_r);
      const double scale_w = radii_up(W(3, 3) / w_w);
      return radii_up(std::max(scale_r, scale_w) * (1.0 + 1e-15)) ;
    }
  }
  return kInf;
}

}  // namespace

double radius_over_sqrt_up(double r, double x) { return radii_up(r / radii_down(std::sqrt(x))); }

double proved_schur_lower(const StateMetric& m, StateBlock block) {
  // rounding site: ball-projection — λ_min of the Schur complement, proved from below.
  const Mat3 X = block == StateBlock::attitude ? attitude_schur(m) : omega_schur(m);
  const double lam_f = lambda_min(X);
  if (!(lam_f > 0.0) || !std::isfinite(lam_f)) return 0.0;
  const Mat6 M = metric_matrix(m);
  for (int attempt = 0; attempt < kAttempts; ++attempt) {
    const double lam = lam_f * (1.0 - widening(attempt));
    if (prove_less(block_selector(block, lam), M).proved) return lam;
  }
  return 0.0;
}

double proved_projection_radius(const StateMetric& m, double r, StateBlock block) {
  const double lam = proved_schur_lower(m, block);
  if (!(lam > 0.0)) return kInf;
  return radius_over_sqrt_up(r, lam);
}

Vec3 proved_omega_half_widths(const StateMetric& m, double r) {
  // rounding site: omega-half-widths — r √((M⁻¹)_kk) proved from above by M ≻ (r/h)² e eᵀ.
  const Vec3 h_f = p_ball_half_widths(omega_schur(m), r);
  const Mat6 M = metric_matrix(m);
  Vec3 out = Vec3::Constant(kInf);
  if (!(r > 0.0)) return Vec3::Zero();
  for (int k = 0; k < 3; ++k) {
    for (int attempt = 0; attempt < kAttempts && !std::isfinite(out(k)); ++attempt) {
      const double h = h_f(k) * (1.0 + widening(attempt));
      if (!(h > 0.0) || !std::isfinite(h)) break;
      const double q = r / h;
      const double alpha = radii_down(q * q * (1.0 - 4e-16));  // ≤ (r/h)², any positive float works
      Mat6 E = Mat6::Zero();
      E(3 + k, 3 + k) = alpha;
      // M ≻ α e eᵀ ⟺ 1 − α eᵀM⁻¹e > 0 (M ≻ 0 follows): r√(eᵀM⁻¹e) < r/√α.
      if (prove_less(E, M).proved) out(k) = radius_over_sqrt_up(r, alpha);
    }
  }
  return out;
}

double proved_cover_radius(const StateMetric& m, double a, double b) {
  // rounding site: cover-radius — sup zᵀMz over the product set, proved from above.
  if (!(a >= 0.0) || !(b >= 0.0)) return kInf;
  if (a == 0.0 && b == 0.0) return 0.0;
  const Mat6 M = metric_matrix(m);
  // A zero radius leaves its block's weight free: any large weight dominates M there.
  const double big = 1e6 * (std::abs(max_eigenvalue(M)) + 1.0);
  // The weights are scanned in double precision; only the best is proved (the next ones only
  // when its proof fails).
  std::vector<std::array<double, 3>> candidates;  // (λ_f, w_R, w_ω)
  auto consider = [&](double th) {
    // w_R a² + w_ω b² ≤ 1: w_R = θ/a², w_ω = (1 − θ)/b², each rounded down.
    const double w_r = a > 0.0 ? radii_down(radii_down(th) / radii_up(a * a)) : big;
    const double w_w = b > 0.0 ? radii_down(radii_down(1.0 - th) / radii_up(b * b)) : big;
    if (!(w_r > 0.0) || !(w_w > 0.0)) return;
    const double lam_f = weighted_max(M, w_r, w_w);
    if (lam_f > 0.0 && std::isfinite(lam_f)) candidates.push_back({lam_f, w_r, w_w});
  };
  if (a > 0.0 && b > 0.0) {
    const double lq = lambda_max(m.Q) * a * a;
    const double lp = lambda_max(m.P) * b * b;
    const double s = Eigen::JacobiSVD<Mat3>(m.S).singularValues()(0) * a * b;
    consider((lq + s) / (lq + lp + 2.0 * s));
    for (int k = 1; k < 40; ++k) consider(k / 40.0);
  } else {
    consider(a > 0.0 ? 1.0 : 0.0);
  }
  std::sort(candidates.begin(), candidates.end());
  for (const auto& [lam_f, w_r, w_w] : candidates) {
    const double lam = proved_weighted_max(M, w_r, w_w, lam_f);
    if (std::isfinite(lam)) return radii_up(std::sqrt(lam));
  }
  return kInf;
}

double proved_ball_growth(double r, double c, double dt, double allowance) {
  // rounding site: ball-growth — r e^{cΔt} + allowance rounded up.
  const double x = radii_up(c * dt);
  const double e = radii_up(radii_up(std::exp(x)));
  return radii_up(radii_up(r * e) + allowance);
}

}  // namespace attiguard::reach
