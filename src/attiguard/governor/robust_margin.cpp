#include "attiguard/governor/robust_margin.hpp"
#include "attiguard/lie/symmetric_eigen.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "attiguard/core/four_digits.hpp"
#include "attiguard/control/pd_so3.hpp"
#include "attiguard/core/errors.hpp"
#include "attiguard/core/finite.hpp"

namespace attiguard::governor {

namespace {

/// Throws SetupError("robust margins: what") unless ok.
void require_robust(bool ok, const std::string& what) {
  if (!ok) throw SetupError("robust margins: " + what);
}

/// Cells of the angle sweep of ultimate_level_bound, and its rounds of refinement.
constexpr int kAngleCells = 4096;
constexpr int kRefinementRounds = 12;
/// Cells of the coarse sweep that ranks the candidate values of ε (any ε is sound; the chosen
/// one's Γ_min is then computed by ultimate_level_bound).
constexpr int kSearchCells = 256;
/// Candidate values of ε tried between ε_max·1e-6 and ε_max.
constexpr int kEpsilonCandidates = 120;

}  // namespace

namespace {

/// ultimate_level_bound over `cells` initial cells and at most `rounds` rounds of refinement.
double level_bound(double a, double b, double c, double epsilon, double u_yy, double u_xx, double u_xy,
                   int cells, int rounds) {
  // Q(x, y) = a y² + b x² − c x y = uᵀ M u with M = [[b, −c/2], [−c/2, a]] (u = (x, y)).
  const double mean = 0.5 * (a + b);
  const double radius = std::hypot(0.5 * (a - b), 0.5 * c);
  const double q_min = mean - radius;  // smallest eigenvalue of M: Q(u) ≥ q_min on the unit circle
  if (!(q_min > 0.0) || !(4.0 * a * b > c * c)) {
    return std::numeric_limits<double>::infinity();
  }
  // Along the ray r·(cos t, sin t), Q ≤ (y + εx) holds for r ≤ B(t)/Q(t), where U = r² U(t):
  // sup = max_t U(t) B(t)² / Q(t)². A cell [t0, t1] is bounded by interval evaluation (every
  // term is monotone in cos t, sin t ≥ 0); cells whose bound exceeds the best point value by more
  // than 1e-6 (relative) are split (branch and bound, at most kMaxRounds rounds).
  const auto value = [&](double t) {
    const double x = std::cos(t);
    const double y = std::sin(t);
    const double q = a * y * y + b * x * x - c * x * y;
    const double r = (y + epsilon * x) / q;
    return r * r * (u_yy * y * y + u_xx * x * x + u_xy * x * y);
  };
  const auto cell_bound = [&](double t0, double t1) {
    const double C0 = std::min(1.0, std::cos(t0));
    const double C1 = std::max(0.0, std::cos(t1));
    const double S0 = std::max(0.0, std::sin(t0));
    const double S1 = std::min(1.0, std::sin(t1));
    const double U_hi = u_yy * S1 * S1 + u_xx * C0 * C0 + u_xy * C0 * S1;
    const double B_hi = S1 + epsilon * C0;
    const double Q_lo = std::max(a * S0 * S0 + b * C1 * C1 - c * C0 * S1, q_min);
    return U_hi * B_hi * B_hi / (Q_lo * Q_lo);
  };
  struct Cell {
    double t0, t1, bound;
  };
  std::vector<Cell> open;
  open.reserve(static_cast<std::size_t>(cells));
  double lower = 0.0;
  const double dt = 0.5 * std::numbers::pi / cells;
  for (int i = 0; i < cells; ++i) {
    const double t0 = i * dt;
    const double t1 = (i + 1 == cells) ? 0.5 * std::numbers::pi : (i + 1) * dt;
    open.push_back({t0, t1, cell_bound(t0, t1)});
    lower = std::max(lower, value(0.5 * (t0 + t1)));
  }
  constexpr int kSplit = 8;
  for (int round = 0; round < rounds && !open.empty(); ++round) {
    std::vector<Cell> next;
    for (const Cell& cell : open) {
      if (!(cell.bound > lower * (1.0 + 1e-6))) continue;
      const double w = (cell.t1 - cell.t0) / kSplit;
      for (int j = 0; j < kSplit; ++j) {
        const double t0 = cell.t0 + j * w;
        const double t1 = j + 1 == kSplit ? cell.t1 : t0 + w;
        next.push_back({t0, t1, cell_bound(t0, t1)});
        lower = std::max(lower, value(0.5 * (t0 + t1)));
      }
    }
    open = std::move(next);
  }
  double sup = lower * (1.0 + 1e-6);
  for (const Cell& cell : open) {
    if (cell.bound > lower * (1.0 + 1e-6)) sup = std::max(sup, cell.bound);
  }
  return sup * (1.0 + 1e-9);  // rounding allowance of the ~20 operations per cell
}

}  // namespace

double ultimate_level_bound(double a, double b, double c, double epsilon, double u_yy, double u_xx,
                            double u_xy) {
  return level_bound(a, b, c, epsilon, u_yy, u_xx, u_xy, kAngleCells, kRefinementRounds);
}

double strict_lyapunov(const lie::Mat3& J, const lie::Mat3& R_ib, const lie::Vec3& omega_b,
                       const lie::Mat3& R_g, double kp, double epsilon) noexcept {
  const lie::Vec3 s = lie::vee(lie::sk(R_ib.transpose() * R_g));
  return control::pd_lyapunov(J, R_ib, omega_b, R_g, {kp, 1.0}) - epsilon * omega_b.dot(J * s);
}

double command_error_bound(const RobustMarginInputs& in) noexcept {
  return in.kp * in.attitude_noise + in.kd * in.rate_error + in.quantisation_error;
}

namespace {

/// The inputs of compute_robust_margin checked: gains, flight loop, delay, finite non-negative
/// error bounds, ε_Γ ∈ (0, 2), 0 < Γ_top ≤ k_p(2 − ε_Γ) (docs/pet-erg.md, section 13).
void require_valid_inputs(const RobustMarginInputs& in) {
  require_robust(positive_finite(in.kp) && positive_finite(in.kd), "kp and kd must be positive and finite");
  require_robust(positive_finite(in.control_period), "needs the flight loop: control_period > 0");
  require_robust(in.delay_periods == 0 || in.delay_periods == 1, "delay_periods must be 0 or 1");
  for (const double x : {in.attitude_bias, in.attitude_noise, in.rate_error, in.quantisation_error, in.disturbance,
                         in.wheel_momentum_max}) {
    require_robust(non_negative_finite(x), "error bounds must be finite and non-negative");
  }
  require_robust(positive_finite(in.applied_torque_max), "the applied torque bound must be positive");
  require_robust(std::isfinite(in.epsilon_gamma) && in.epsilon_gamma > 0.0 && in.epsilon_gamma < 2.0,
          "epsilon_gamma must lie in (0, 2)");
  require_robust(positive_finite(in.gamma_top) && in.gamma_top <= in.kp * (2.0 - in.epsilon_gamma) * (1.0 + 1e-12),
          "gamma_top must be positive and at most kp (2 - epsilon_gamma)");
}

/// The inertia's extreme moments and the bounds on the level set {V ≤ Γ_top} the margin uses.
struct LevelSet {
  double lmin{0.0};       ///< λ_min(J)
  double lmax{0.0};       ///< λ_max(J)
  double phi_top{0.0};    ///< the largest φ on it
  double theta_top{0.0};  ///< the largest attitude-error angle on it
  double gyro{0.0};       ///< ½(λ_max − λ_min): ‖Jω × ω‖ ≤ gyro ‖ω‖²
  double H{0.0};          ///< ‖A h‖ of the wheels
};

/// λ_min, λ_max of J (refused unless positive definite) and, into m, ω_max and s_max on
/// {V ≤ Γ_top}: ½λ_min‖ω‖² ≤ V, k_p φ ≤ V, ‖s‖² = φ(2 − φ).
LevelSet level_set(const RobustMarginInputs& in, RobustMargin& m) {
  const lie::Vec3 moments = lie::symmetric_eigenvalues(in.J);
  LevelSet g;
  g.lmin = moments(0);
  g.lmax = moments(2);
  require_robust(positive_finite(g.lmin) && positive_finite(g.lmax), "the inertia must be positive definite");
  g.phi_top = std::min(in.gamma_top / in.kp, 2.0 - in.epsilon_gamma);
  m.omega_max = std::sqrt(2.0 * in.gamma_top / g.lmin);
  m.s_max = g.phi_top >= 1.0 ? 1.0 : std::sqrt(g.phi_top * (2.0 - g.phi_top));
  g.theta_top = std::acos(std::clamp(1.0 - g.phi_top, -1.0, 1.0));
  g.gyro = 0.5 * (g.lmax - g.lmin);
  g.H = in.wheel_momentum_max;
  return g;
}

/// The torque-error budget w̄ into m (docs/pet-erg.md, section 13, "Error budget"): sensors,
/// quantisation, the staleness of the held torque, the delayed command's older R_g, disturbance.
void error_budget(const RobustMarginInputs& in, const LevelSet& g, RobustMargin& m) {
  const double kp = in.kp;
  const double kd = in.kd;
  const double h = in.control_period;
  const int d = in.delay_periods;
  m.sensor_error = kp * in.attitude_noise + kd * in.rate_error;
  m.quantisation_error = in.quantisation_error;
  m.command_error = command_error_bound(in);
  m.disturbance = in.disturbance;
  // The applied torque is the quantised command of a state in {V ≤ Γ_top}: its PD torque is at
  // most √(2k_p + 2k_d²/λ_min) √Γ_top (the loose bound of docs/pet-erg.md section 2), plus e_cmd.
  const double applied = std::min(in.applied_torque_max,
                                  std::sqrt(2.0 * kp + 2.0 * kd * kd / g.lmin) * std::sqrt(in.gamma_top) +
                                      m.command_error);
  const double omega_dot_max =
      (g.gyro * m.omega_max * m.omega_max + g.H * m.omega_max + applied + in.disturbance) / g.lmin;
  const double torque_rate_max = kp * m.omega_max + kd * omega_dot_max;  // ‖d/dt τ_PD‖ ≤ this
  m.hold_error = (1.0 + d) * h * torque_rate_max;
  if (d == 0) {
    m.max_reference_step = std::numeric_limits<double>::infinity();
    m.reference_lag_error = 0.0;
  } else {
    m.max_reference_step = in.max_reference_step > 0.0
                               ? in.max_reference_step
                               : (m.disturbance + m.command_error + m.hold_error) / (4.0 * kp);
    require_robust(positive_finite(m.max_reference_step), "the reference step cap must be positive and finite");
    m.reference_lag_error = d * kp * m.max_reference_step;
  }
  m.torque_error = m.disturbance + m.command_error + m.hold_error + m.reference_lag_error;
}

/// ε of W = V − ε ωᵀJ s chosen on a grid to minimise Γ_min/(1 − δ), with a = k_d − ελ_max > 0,
/// δ = ε√(λ_max/k_p) < 1 and 4ab > c², c = ε(k_d + gyro ω_max + H) + k_p β (the bias term
/// k_p ωᵀ(I − B)s of V̇, ‖I − B‖ ≤ β); then Γ_min of the chosen ε, certified, into m
/// (docs/pet-erg.md, section 13). Refused when no ε gives a strict Lyapunov function.
void choose_epsilon(const RobustMarginInputs& in, const LevelSet& g, RobustMargin& m) {
  const double kp = in.kp;
  const double kd = in.kd;
  const double lmax = g.lmax;
  const double wbar = m.torque_error;
  const double C = kd + g.gyro * m.omega_max + g.H;
  const double bias_coupling = kp * 2.0 * std::sin(0.5 * std::min(in.attitude_bias, std::numbers::pi));
  const double eps_max = std::min({kd / lmax, std::sqrt(kp / lmax), 4.0 * kp * kd / (4.0 * kp * lmax + C * C)});
  double best_score = std::numeric_limits<double>::infinity();
  for (int i = 0; i < kEpsilonCandidates; ++i) {
    const double eps = eps_max * std::pow(10.0, -6.0 * (1.0 - (i + 0.5) / kEpsilonCandidates));
    const double delta = eps * std::sqrt(lmax / kp);
    const double a = kd - eps * lmax;
    const double b = eps * kp;
    const double c = eps * C + bias_coupling;
    const double unit = level_bound(a, b, c, eps, 0.5 * lmax, kp / (2.0 - g.phi_top), eps * lmax, kSearchCells, 0);
    if (!std::isfinite(unit) || !(delta < 1.0)) continue;
    const double gamma_min = wbar * wbar * unit;
    const double score = gamma_min / (1.0 - delta);
    if (score < best_score) {
      best_score = score;
      m.epsilon = eps;
      m.delta = delta;
      m.a = a;
      m.b = b;
      m.c = c;
      m.gamma_min = gamma_min;
    }
  }
  if (m.epsilon > 0.0) {
    m.gamma_min = wbar * wbar * ultimate_level_bound(m.a, m.b, m.c, m.epsilon, 0.5 * lmax, kp / (2.0 - g.phi_top),
                                                     m.epsilon * lmax);
  }
  require_robust(m.epsilon > 0.0, "no strict Lyapunov function W = V - eps w^T J s for kp = " + four_digits(kp) +
                               ", kd = " + four_digits(kd) + " and the inertia's lambda_max = " + four_digits(lmax) +
                               (bias_coupling > 0.0 ? " with the attitude bias coupling kp 2 sin(beta/2) = " +
                                                          four_digits(bias_coupling) + " N m (beta = " + four_digits(in.attitude_bias) +
                                                          " rad): reduce the bias bound or raise kd"
                                                    : ": raise kd"));
}

}  // namespace

RobustMargin compute_robust_margin(const RobustMarginInputs& in) {
  require_valid_inputs(in);
  RobustMargin m;
  const LevelSet g = level_set(in, m);
  error_budget(in, g, m);
  choose_epsilon(in, g, m);
  const double kp = in.kp;
  const double sr = in.attitude_noise;
  const double sw = in.rate_error;
  m.measurement_margin = g.lmax * (m.omega_max * sw + 0.5 * sw * sw) +
                         kp * sr * std::min(1.0, g.theta_top + sr) +
                         m.epsilon * g.lmax * (sw * (m.s_max + sr) + m.omega_max * sr);
  const double pd_torque_max = kp * m.s_max + in.kd * m.omega_max;
  m.start_allowance = in.delay_periods * in.control_period * (in.disturbance + pd_torque_max) *
                      (m.omega_max + m.epsilon * m.s_max);
  return m;
}

}  // namespace attiguard::governor
