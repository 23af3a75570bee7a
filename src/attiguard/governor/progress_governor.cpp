#include "attiguard/governor/progress_governor.hpp"

#include <algorithm>
#include <utility>
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
/// a = kClockAccelerationPlans / T_p: the clock stops from ṡ = 1 within a quarter of the plan.
constexpr double kClockAccelerationPlans = 4.0;
/// Braking candidates −a, −a/2, …, −a/2^(kBrakeSteps−1).
constexpr int kBrakeSteps = 6;
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
  accel_max_ = kClockAccelerationPlans / plan.duration();
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
    double d_omega = 0.0, d_omega_dot = 0.0, d_margin = 0.0;
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
      if (std::isfinite(margin)) d_margin = std::max(d_margin, std::abs(margin - prev_margin));
      prev = s;
      prev_margin = margin;
    }
    e.omega_max += d_omega;
    e.omega_dot_max += d_omega_dot;
    // The torque is linear between the node, the midpoint and the next node, and a norm is
    // convex along a segment: its largest value is at one of the three, exactly.
    e.tau_max = std::max({nodes[static_cast<std::size_t>(k)].tau_b.norm(),
                          plan.midpoint_torques()[static_cast<std::size_t>(k)].norm(),
                          nodes[static_cast<std::size_t>(k + 1)].tau_b.norm()});
    e.cone_margin_min -= d_margin;
    extremes_.push_back(e);
  }
  suffix_ = extremes_;
  for (int k = plan.intervals() - 2; k >= 0; --k) {
    IntervalExtremes& e = suffix_[static_cast<std::size_t>(k)];
    const IntervalExtremes& next = suffix_[static_cast<std::size_t>(k + 1)];
    e.omega_max = std::max(e.omega_max, next.omega_max);
    e.omega_dot_max = std::max(e.omega_dot_max, next.omega_dot_max);
    e.tau_max = std::max(e.tau_max, next.tau_max);
    e.cone_margin_min = std::min(e.cone_margin_min, next.cone_margin_min);
  }
  suffix_gamma_g_.reserve(suffix_.size());
  for (const IntervalExtremes& e : suffix_) {
    suffix_gamma_g_.push_back(cone_threshold(PlanWindow{0.0, 0.0, 0.0, e.cone_margin_min}));
  }
}

int ProgressGovernor::interval_of(double t) const noexcept {
  const auto nodes = plan_.nodes();
  const auto it = std::upper_bound(nodes.begin(), nodes.end(), t,
                                   [](double v, const SlewPlanNode& n) { return v < n.t; });
  const auto k = static_cast<int>(it - nodes.begin()) - 1;
  return std::clamp(k, 0, plan_.intervals() - 1);
}

PlanWindow ProgressGovernor::ahead(double sigma) const noexcept {
  const IntervalExtremes& e = suffix_[static_cast<std::size_t>(interval_of(sigma))];
  return PlanWindow{e.omega_max, e.omega_dot_max, e.tau_max, e.cone_margin_min};
}

double ProgressGovernor::cone_threshold_ahead(double sigma) const noexcept {
  return suffix_gamma_g_[static_cast<std::size_t>(interval_of(sigma))];
}

PlanWindow ProgressGovernor::window(double from, double to) const noexcept {
  const double T = plan_.duration();
  from = std::clamp(from, 0.0, T);
  to = std::clamp(std::max(from, to), 0.0, T);
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

double ProgressGovernor::torque_bound(double gamma, double rate, const PlanWindow& w,
                                      double accel) const noexcept {
  // V = ½ e_Ωᵀ J e_Ω + k_R φ ≤ Γ splits Γ between the attitude error (f Γ) and the rate error
  // ((1 − f) Γ). The terms in θ grow with f, those in E fall with f: over a cell [f_i, f_{i+1}]
  // the bound is at most the θ terms at f_{i+1} plus the E terms at f_i, and the largest of
  // those over kSplitCells cells bounds every split (docs/pet-erg.md, section 16.1, "Torque").
  // With the clock's acceleration s̈ the reference's ω̇_d = ṡ² ω̇_p + s̈ ω_p and its torque
  // ṡ² τ_p + s̈ J ω_p: ‖ω̇_d‖ ≤ ṡ²‖ω̇_p‖ + |s̈|‖ω_p‖, ‖·‖ ≤ ṡ²‖τ_p‖ + |s̈| λ_max ‖ω_p‖.
  gamma = std::max(0.0, gamma);
  const auto attitude_angle = [&](double f) {
    // 1 − cos θ = x: sin θ = √(x(2 − x)) while θ < π/2, and θ = 2 asin √(x/2) is at most
    // √(2x/(1 − x/2)) (asin y ≤ y/√(1 − y²)), tight for small θ; acos beyond x = 1.
    const double x = std::min(2.0, f * gamma / gains_.k_R);
    const double sin_bound = x < 1.0 ? std::sqrt(x * (2.0 - x)) : 1.0;
    const double theta = x < 1.0 ? std::sqrt(2.0 * x / (1.0 - 0.5 * x)) : std::acos(1.0 - x);
    return std::pair{sin_bound, theta};
  };
  const auto rate_error = [&](double f) { return std::sqrt(2.0 * (1.0 - f) * gamma / lambda_min_); };
  const auto bound = [&](double f_attitude, double f_rate) {
    const auto [sin_bound, theta] = attitude_angle(f_attitude);
    const double E = rate_error(f_rate);
    return gains_.k_R * sin_bound + gains_.k_Omega * E + feedforward_error(theta, E, rate, w, accel);
  };
  const double reference = reference_torque(rate, w, accel);
  // Both errors at the full Γ bounds every split: within τ_max, that coarse bound is the answer
  // (one evaluation, the flight loop's usual case); else the cells.
  const double coarse = bound(1.0, 0.0) + reference;
  if (coarse <= tau_max_) return coarse;
  double worst = 0.0;
  for (int i = 0; i < kSplitCells; ++i) {
    const double f0 = static_cast<double>(i) / kSplitCells;
    const double f1 = static_cast<double>(i + 1) / kSplitCells;
    worst = std::max(worst, bound(f1, f0));
  }
  return worst + reference;
}

double ProgressGovernor::feedforward_error(double theta, double E, double rate, const PlanWindow& w,
                                           double accel) const noexcept {
  const double s2 = rate * rate;
  const double a = std::abs(accel);
  const double spread =
      (lambda_max_ - lambda_min_) * (s2 * (w.omega_max * w.omega_max + w.omega_dot_max) + a * w.omega_max);
  // With ω = v + e_Ω (v = R_e ω_d) the law's gyroscopic and transport terms leave, beyond the
  // reference's, B(e, v) + e × J e with B(e, v) = v × J e + e × J v − J (e × v). Writing
  // J = c I + D, c = ½(λ_max + λ_min), ‖D‖ ≤ ½(λ_max − λ_min): B = c v × e + (terms in D), so
  // ‖B‖ ≤ (c + 3‖D‖)‖e‖‖v‖ = (2λ_max − λ_min)‖e‖‖v‖, and e × J e = e × D e ≤ ½(λ_max − λ_min)‖e‖².
  return theta * spread + 0.5 * (lambda_max_ - lambda_min_) * E * E +
         (2.0 * lambda_max_ - lambda_min_) * E * rate * w.omega_max;
}

double ProgressGovernor::reference_torque(double rate, const PlanWindow& w, double accel) const noexcept {
  return rate * rate * w.tau_max + std::abs(accel) * lambda_max_ * w.omega_max;
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
control::TrackingReference scaled(const SlewPlanSample& s, bool at_end, double rate,
                                  double accel) noexcept {
  if (at_end) return control::TrackingReference{s.R_ib, lie::Vec3::Zero(), lie::Vec3::Zero()};
  return control::TrackingReference{s.R_ib, rate * s.omega_b,
                                    rate * rate * s.omega_dot_b + accel * s.omega_b};
}

}  // namespace

control::TrackingReference ProgressGovernor::reference(double sigma, double rate,
                                                       double accel) const noexcept {
  return scaled(plan_.evaluate(sigma), sigma >= plan_.duration(), rate, accel);
}

control::TrackingReference ProgressGovernor::reference(const SlewPlanSample& at_sigma, double sigma,
                                                       double rate, double accel) const noexcept {
  return scaled(at_sigma, sigma >= plan_.duration(), rate, accel);
}

RateChoice ProgressGovernor::choose(double sigma, const lie::Mat3& R_ib, const lie::Vec3& omega_b,
                                   double rate) const noexcept {
  return choose(plan_.evaluate(sigma), sigma, R_ib, omega_b, rate);
}

RateChoice ProgressGovernor::choose(const SlewPlanSample& s, double sigma, const lie::Mat3& R_ib,
                                   const lie::Vec3& omega_b, double rate) const noexcept {
  // V(ṡ) = ½(ω − ṡ v)ᵀJ(ω − ṡ v) + k_R φ(R_e), v = R_e ω_p(σ): R_e, v and φ once for every
  // candidate (docs/pet-erg.md, section 16.1, "Choice of ṡ").
  const bool at_end = sigma >= plan_.duration();
  rate = std::clamp(rate, 0.0, 1.0);
  const lie::Mat3 R_e = R_ib.transpose() * s.R_ib;
  const lie::Vec3 v = at_end ? lie::Vec3::Zero() : lie::Vec3(R_e * s.omega_b);
  const double attitude_part = gains_.k_R * lie::phi(R_e);
  const auto level = [&](double r) {
    const lie::Vec3 e = omega_b - r * v;
    return 0.5 * e.dot(J_b_ * e) + attitude_part;
  };
  const auto k = static_cast<std::size_t>(interval_of(sigma));
  const IntervalExtremes& e = suffix_[k];
  const PlanWindow w{e.omega_max, e.omega_dot_max, e.tau_max, e.cone_margin_min};
  const double keep = 1.0 - epsilon_;
  RateChoice c;
  c.gamma_g = suffix_gamma_g_[k];
  // Admissible: V ≤ (1 − ε)Γ_g and the bound of {V ≤ V/(1 − ε)} at the period's largest rate.
  const auto holds = [&](double V, double top_rate, double accel) {
    c.V = V;
    c.torque_bound = torque_bound(V / keep, top_rate, w, accel);
    return V <= keep * c.gamma_g && c.torque_bound <= tau_max_;
  };
  const double V_now = level(rate);
  if (at_end) {  // the hold: the reference at rest, the rate no longer matters
    c.rate = rate;
    c.admissible = holds(V_now, 0.0, 0.0);
    return c;
  }
  for (int i = kRateSteps; i >= 1 && static_cast<double>(i) / kRateSteps > rate; --i) {
    const double r = static_cast<double>(i) / kRateSteps;
    if (holds(level(r), r, 0.0)) {
      c.rate = r;
      c.rule = RateRule::jump;
      c.admissible = true;
      return c;
    }
  }
  c.rate = rate;
  if (rate < 1.0 && holds(V_now, std::min(1.0, rate + accel_max_ * sample_period_), accel_max_)) {
    c.accel = accel_max_;
    c.rule = RateRule::accelerate;
    c.admissible = true;
    return c;
  }
  if (holds(V_now, rate, 0.0)) {
    c.rule = RateRule::coast;
    c.admissible = true;
    return c;
  }
  c.rule = RateRule::brake;
  if (rate > 0.0) c.accel = brake_acceleration(sigma, R_ib, omega_b, rate);
  return c;
}

double ProgressGovernor::brake_acceleration(double sigma, const lie::Mat3& R_ib,
                                            const lie::Vec3& omega_b, double rate) const noexcept {
  // The candidate whose tracking torque now is the smallest, the strongest braking on a tie:
  // braking the clock lowers the torque while the plan accelerates and raises it while the plan
  // brakes, where the clock coasts.
  double best = 0.0;
  double best_torque = control::tracking_torque(J_b_, R_ib, omega_b, reference(sigma, rate, 0.0), gains_).norm();
  for (int i = kBrakeSteps - 1; i >= 0; --i) {
    const double accel = -accel_max_ / static_cast<double>(1 << i);
    const double torque =
        control::tracking_torque(J_b_, R_ib, omega_b, reference(sigma, rate, accel), gains_).norm();
    if (torque <= best_torque) {
      best_torque = torque;
      best = accel;
    }
  }
  return best;
}

}  // namespace attiguard::governor
