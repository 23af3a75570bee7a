#include "attiguard/governor/progress_governor.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <Eigen/Eigenvalues>

#include "attiguard/core/errors.hpp"

namespace attiguard::governor {

namespace {

/// θ_c − ∠(a_c, R a_b): the angle by which R keeps the cone [rad] (≥ 0 when kept).
double angle_margin(const ConeConstraint& cone, const lie::Mat3& R_ib) noexcept {
  const double c = std::clamp(cone.direction_i.dot(R_ib * cone.axis_b), -1.0, 1.0);
  return cone.theta_c - std::acos(c);
}

/// Rates of `steps` candidate values of ṡ tried by choose_rate: 1, 31/32, …, 1/32, 0.
constexpr int kRateSteps = 32;
/// Cells of the split of Γ between the attitude and the rate error in the torque bound.
constexpr int kSplitCells = 16;
/// Bisection steps of Γ_d (relative resolution 2⁻⁶⁰ of 2 k_R).
constexpr int kBisections = 60;

}  // namespace

ProgressGovernor::ProgressGovernor(const SlewPlan& plan, std::span<const ConeConstraint> cones,
                                   double tau_max, const control::TrackingGains& gains,
                                   double sample_period, double epsilon, int points_per_interval)
    : plan_(plan), J_b_(plan.inertia()), tau_max_(tau_max), gains_(gains),
      sample_period_(sample_period), epsilon_(epsilon) {
  if (plan.intervals() < 1) throw SetupError("progress governor: the plan has no interval");
  if (!(tau_max > 0.0) || !(gains.k_R > 0.0) || !(gains.k_Omega > 0.0) || !(sample_period > 0.0) ||
      !(epsilon >= 0.0 && epsilon < 1.0) || points_per_interval < 2) {
    throw SetupError("progress governor: tau_max, the gains and the sampling period must be > 0, "
                     "epsilon in [0, 1), at least 2 points per interval");
  }
  const Eigen::SelfAdjointEigenSolver<lie::Mat3> eig(J_b_);
  lambda_min_ = eig.eigenvalues().minCoeff();
  lambda_max_ = eig.eigenvalues().maxCoeff();
  const auto nodes = plan.nodes();
  extremes_.reserve(static_cast<std::size_t>(plan.intervals()));
  for (int k = 0; k < plan.intervals(); ++k) {
    const double ta = nodes[static_cast<std::size_t>(k)].t;
    const double tb = nodes[static_cast<std::size_t>(k + 1)].t;
    // Sampled extremes, widened by the largest change between neighbouring samples: the
    // interpolants are cubic in t, so between two samples they leave the samples' range by less
    // than that change once the samples are dense (the assumption of these tables).
    IntervalExtremes e{0.0, 0.0, 0.0, std::numeric_limits<double>::infinity()};
    double d_omega = 0.0, d_omega_dot = 0.0, d_tau = 0.0, d_margin = 0.0;
    SlewPlanSample prev = plan.evaluate_in(k, ta);
    double prev_margin = std::numeric_limits<double>::infinity();
    for (const ConeConstraint& c : cones) prev_margin = std::min(prev_margin, angle_margin(c, prev.R_ib));
    for (int i = 0; i <= points_per_interval; ++i) {
      const SlewPlanSample s = plan.evaluate_in(k, ta + (tb - ta) * i / points_per_interval);
      double margin = std::numeric_limits<double>::infinity();
      for (const ConeConstraint& c : cones) margin = std::min(margin, angle_margin(c, s.R_ib));
      e.omega_max = std::max(e.omega_max, s.omega_b.norm());
      e.omega_dot_max = std::max(e.omega_dot_max, s.omega_dot_b.norm());
      e.tau_max = std::max(e.tau_max, s.tau_b.norm());
      e.cone_margin_min = std::min(e.cone_margin_min, margin);
      d_omega = std::max(d_omega, std::abs(s.omega_b.norm() - prev.omega_b.norm()));
      d_omega_dot = std::max(d_omega_dot, std::abs(s.omega_dot_b.norm() - prev.omega_dot_b.norm()));
      d_tau = std::max(d_tau, std::abs(s.tau_b.norm() - prev.tau_b.norm()));
      if (std::isfinite(margin)) d_margin = std::max(d_margin, std::abs(margin - prev_margin));
      prev = s;
      prev_margin = margin;
    }
    e.omega_max += d_omega;
    e.omega_dot_max += d_omega_dot;
    e.tau_max += d_tau;
    e.cone_margin_min -= d_margin;
    extremes_.push_back(e);
  }
}

PlanWindow ProgressGovernor::window(double from, double to) const noexcept {
  const auto nodes = plan_.nodes();
  const double T = plan_.duration();
  from = std::clamp(from, 0.0, T);
  to = std::clamp(std::max(from, to), 0.0, T);
  const auto interval_of = [&](double t) {
    const auto it = std::upper_bound(nodes.begin(), nodes.end(), t,
                                     [](double v, const SlewPlanNode& n) { return v < n.t; });
    const auto k = static_cast<int>(it - nodes.begin()) - 1;
    return std::clamp(k, 0, plan_.intervals() - 1);
  };
  PlanWindow w{0.0, 0.0, 0.0, std::numeric_limits<double>::infinity()};
  for (int k = interval_of(from); k <= interval_of(to); ++k) {
    const IntervalExtremes& e = extremes_[static_cast<std::size_t>(k)];
    w.omega_max = std::max(w.omega_max, e.omega_max);
    w.omega_dot_max = std::max(w.omega_dot_max, e.omega_dot_max);
    w.tau_max = std::max(w.tau_max, e.tau_max);
    w.cone_margin_min = std::min(w.cone_margin_min, e.cone_margin_min);
  }
  return w;
}

double ProgressGovernor::cone_threshold(const PlanWindow& w) const noexcept {
  const double m = w.cone_margin_min;
  if (!(m > 0.0)) return 0.0;
  if (m >= std::numbers::pi) return 2.0 * gains_.k_R;
  return gains_.k_R * (1.0 - std::cos(m));
}

double ProgressGovernor::torque_bound(double gamma, double rate, const PlanWindow& w) const noexcept {
  // V = ½ e_Ωᵀ J e_Ω + k_R φ ≤ Γ splits Γ between the attitude error (f Γ) and the rate error
  // ((1 − f) Γ). The terms in θ grow with f, those in E fall with f: over a cell [f_i, f_{i+1}]
  // the bound is at most the θ terms at f_{i+1} plus the E terms at f_i, and the largest of
  // those over kSplitCells cells bounds every split (docs/pet-erg.md, section 16.1, "Torque").
  gamma = std::max(0.0, gamma);
  const double s2 = rate * rate;
  const auto attitude_terms = [&](double f) {
    const double theta = std::acos(std::max(-1.0, 1.0 - f * gamma / gains_.k_R));
    const double sin_bound = theta < 0.5 * std::numbers::pi ? std::sin(theta) : 1.0;
    return gains_.k_R * sin_bound +
           theta * (lambda_max_ - lambda_min_) * s2 * (w.omega_max * w.omega_max + w.omega_dot_max);
  };
  const auto rate_terms = [&](double f) {
    const double E = std::sqrt(2.0 * (1.0 - f) * gamma / lambda_min_);
    return gains_.k_Omega * E + lambda_max_ * E * E + 3.0 * lambda_max_ * E * rate * w.omega_max;
  };
  double worst = 0.0;
  for (int i = 0; i < kSplitCells; ++i) {
    const double f0 = static_cast<double>(i) / kSplitCells;
    const double f1 = static_cast<double>(i + 1) / kSplitCells;
    worst = std::max(worst, attitude_terms(f1) + rate_terms(f0));
  }
  return worst + s2 * w.tau_max;
}

double ProgressGovernor::torque_threshold(double rate, const PlanWindow& w) const noexcept {
  if (torque_bound(0.0, rate, w) > tau_max_) return 0.0;
  double lo = 0.0, hi = 2.0 * gains_.k_R;
  if (torque_bound(hi, rate, w) <= tau_max_) return hi;
  for (int i = 0; i < kBisections; ++i) {
    const double mid = 0.5 * (lo + hi);
    (torque_bound(mid, rate, w) <= tau_max_ ? lo : hi) = mid;
  }
  return lo;
}

namespace {

/// The plan's sample at σ flown at the rate ṡ: R_p, ṡ ω_p, ṡ² ω̇_p; at σ ≥ T_p, R_d at rest (the
/// hold): the plan's last ω̇ (its final braking) would otherwise be fed forward for ever.
control::TrackingReference scaled(const SlewPlanSample& s, bool at_end, double rate) noexcept {
  if (at_end) return control::TrackingReference{s.R_ib, lie::Vec3::Zero(), lie::Vec3::Zero()};
  return control::TrackingReference{s.R_ib, rate * s.omega_b, rate * rate * s.omega_dot_b};
}

}  // namespace

control::TrackingReference ProgressGovernor::reference(double sigma, double rate) const noexcept {
  return scaled(plan_.evaluate(sigma), sigma >= plan_.duration(), rate);
}

double ProgressGovernor::choose_rate(double sigma, const lie::Mat3& R_ib,
                                     const lie::Vec3& omega_b) const noexcept {
  const SlewPlanSample s = plan_.evaluate(sigma);  // once: only the rate changes below
  const bool at_end = sigma >= plan_.duration();
  for (int i = kRateSteps; i >= 1; --i) {
    const double rate = static_cast<double>(i) / kRateSteps;
    const PlanWindow w = window(sigma, sigma + rate * sample_period_);
    const double gamma = std::min(cone_threshold(w), torque_threshold(rate, w));
    const double V = control::tracking_lyapunov(J_b_, R_ib, omega_b, scaled(s, at_end, rate), gains_);
    if (V <= (1.0 - epsilon_) * gamma) return rate;
  }
  return 0.0;
}

}  // namespace attiguard::governor
