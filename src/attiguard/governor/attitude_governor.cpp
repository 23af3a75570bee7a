#include "attiguard/governor/attitude_governor.hpp"
#include "attiguard/lie/symmetric_eigen.hpp"

#include "attiguard/core/errors.hpp"
#include "attiguard/core/finite.hpp"

#include <algorithm>
#include <cmath>
#include <bit>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

#include "attiguard/governor/navigation_field.hpp"
#include "attiguard/governor/pointing_threshold.hpp"
#include "attiguard/governor/saddle_tie_break.hpp"

namespace attiguard::governor {

namespace {

void require(bool ok, const std::string& what) {
  if (!ok) {
    throw SetupError("governor: " + what);
  }
}

/// a and b hold the same bits (a memo's key: equal inputs give equal results).
template <class M>
bool same_bits(const M& a, const M& b) noexcept {
  bool same = true;
  for (int i = 0; i < M::SizeAtCompileTime; ++i) {
    same = same && std::bit_cast<std::uint64_t>(a(i)) == std::bit_cast<std::uint64_t>(b(i));
  }
  return same;
}

}  // namespace

double GovernorOutput::min_margin() const noexcept {
  double m = std::numeric_limits<double>::infinity();
  for (int i = 0; i < cone_count; ++i) {
    m = std::min(m, margins[static_cast<std::size_t>(i)]);
  }
  return m;
}

AttitudeGovernor::AttitudeGovernor(const GovernorParams& params,
                                   std::span<const ConeConstraint> cones)
    : params_(params) {
  require(params.mode != GovernorMode::planned,
          "mode \"planned\" flies a planned slew (a scenario with governor = \"planned\", or "
          "governor::PlannedGovernor in C++), not this governor");
  require(positive_finite(params.gains.kp) && positive_finite(params.gains.kd),
          "kp and kd must be positive and finite");
  require(positive_finite(params.tau_max), "tau_max must be positive and finite");
  require(positive_finite(params.kappa), "kappa must be positive and finite");
  require(std::isfinite(params.c_gamma) && params.c_gamma > 1.0, "c_gamma must exceed 1");
  require(positive_finite(params.Ts), "the sampling period Ts must be positive and finite");
  require(positive_finite(params.epsilon), "epsilon must be positive and finite");
  require(std::isfinite(params.epsilon_gamma) && params.epsilon_gamma > 0.0 &&
              params.epsilon_gamma < 2.0,
          "epsilon_gamma must lie in (0, 2)");
  require(params.J.allFinite() && (params.J - params.J.transpose()).norm() <= 1e-9 * params.J.norm(),
          "the inertia matrix must be finite and symmetric");
  const double lambda_min = lie::lambda_min(params.J);
  require(lambda_min > 0.0, "the inertia matrix must be positive definite");
  require(cones.size() <= static_cast<std::size_t>(kMaxCones),
          "at most " + std::to_string(kMaxCones) + " cone constraints");
  for (std::size_t i = 0; i < cones.size(); ++i) {
    if (const auto err = cone_error(cones[i])) {
      throw SetupError("governor: cone " + std::to_string(i) + ": " + *err);
    }
    (void)cones_.push_back(cones[i]);
  }
  const TorqueThresholdInputs in{params.gains.kp, params.gains.kd, lambda_min, params.tau_max};
  threshold_ = compute_torque_threshold(in);
  gamma_d_ = threshold_.gamma_d;
  require(std::isfinite(params.polytope_gamma_d) && params.polytope_gamma_d >= 0.0,
          "polytope_gamma_d must be finite and non-negative");
  if (params.polytope_gamma_d > 0.0) {
    gamma_d_ = std::min(gamma_d_, params.polytope_gamma_d);
  }
  require(!params.robust || params.bounded_step,
          "robust margins need the bounded reference step (the flight loop's, bounded_step)");
  if (params.robust) {
    const RobustMargin& m = *params.robust;
    require(m.epsilon > 0.0 && m.delta >= 0.0 && m.delta < 1.0 && std::isfinite(m.gamma_min) &&
                m.gamma_min >= 0.0 && std::isfinite(m.measurement_margin) && m.measurement_margin >= 0.0 &&
                m.max_reference_step > 0.0,
            "robust margins: use the values of compute_robust_margin");
  }
  gamma_d_loose_ = torque_threshold_loose(in);
  gamma_cap_ = params.gains.kp * (2.0 - params.epsilon_gamma);
  out_.gamma_d = gamma_d_;
  out_.cone_count = cones_.size();
}

double AttitudeGovernor::lyapunov(const Mat3& R_ib, const Vec3& omega_b,
                                  const Mat3& R_g) const noexcept {
  return control::pd_lyapunov(params_.J, R_ib, omega_b, R_g, params_.gains);
}

Vec3 AttitudeGovernor::torque(const Mat3& R_ib, const Vec3& omega_b, const Mat3& R_g) const noexcept {
  return control::pd_torque(R_ib, omega_b, R_g, params_.gains);
}

double AttitudeGovernor::gamma_g(const Mat3& R_g) const noexcept {
  return pointing_threshold(cones_.span(), R_g, params_.gains.kp);
}

inline double AttitudeGovernor::gamma_of(double gamma_g) const noexcept {
  const double nominal = std::min({gamma_d_, gamma_g, gamma_cap_});
  return params_.robust ? (1.0 - params_.robust->delta) * nominal : nominal;
}

double AttitudeGovernor::gamma(const Mat3& R_g) const noexcept { return gamma_of(gamma_g(R_g)); }

double AttitudeGovernor::level(const Mat3& R_ib, const Vec3& omega_b, const Mat3& R_g) const noexcept {
  if (!params_.robust) return lyapunov(R_ib, omega_b, R_g);
  return strict_lyapunov(params_.J, R_ib, omega_b, R_g, params_.gains.kp, params_.robust->epsilon);
}

inline double AttitudeGovernor::decision_level(const Mat3& R_ib, const Vec3& omega_b,
                                        const Mat3& R_g) const noexcept {
  const double W = level(R_ib, omega_b, R_g);
  return params_.robust ? W + params_.robust->measurement_margin : W;
}

bool AttitudeGovernor::admissible_move(const Mat3& R_ib, const Vec3& omega_b,
                                       const Mat3& candidate) const noexcept {
  const double G = gamma(candidate);
  if (params_.robust && !(G > params_.robust->gamma_min)) return false;
  return decision_level(R_ib, omega_b, candidate) <= G;
}

Vec3 AttitudeGovernor::navigation_field(const Mat3& R_g, const Mat3& R_d) const noexcept {
  return governor::navigation_field(cones_.span(), R_g, R_d, std::min(params_.epsilon, kTieBreakFloorCap));
}

bool AttitudeGovernor::trigger_condition(const Mat3& R_ib, const Vec3& omega_b,
                                         const Mat3& R_g) const noexcept {
  return pet_trigger(gamma(R_g), decision_level(R_ib, omega_b, R_g), params_.c_gamma);
}

// flatten: as rates() below (docs/performance.md, "Shared cone cosines").
[[gnu::flatten]] inline GovernorOutput AttitudeGovernor::figures_into(const Mat3& R_ib, const Vec3& omega_b, const Mat3& R_g, const Mat3& R_d,
                                              bool flag, const TieBreak& tie, GovernorMemo* memo) const noexcept {
  GovernorOutput out;
  out.R_g = params_.mode == GovernorMode::none ? R_d : R_g;
  // RᵀR_g once for τ [PET-ERG eq. (3)] and V, each formed from it as pd_torque and pd_lyapunov do.
  const Mat3 R_e = R_ib.transpose() * out.R_g;
  out.tau_b = params_.gains.kp * lie::vee(lie::sk(R_e)) - params_.gains.kd * omega_b;
  out.V = 0.5 * omega_b.dot(params_.J * omega_b) + params_.gains.kp * lie::phi(R_e);
  out.W = params_.robust ? level(R_ib, omega_b, out.R_g) : out.V;
  out.gamma_d = gamma_d_;
  if (memo != nullptr) {
    remember_reference(out.R_g, *memo);
    out.gamma_g = memo->gamma_g;
    memo->has_state = true;
    memo->R_ib = R_ib;
    memo->omega_b = omega_b;
    memo->tau_b = out.tau_b;
    memo->V = out.V;
  } else {
    out.gamma_g = gamma_g(out.R_g);
  }
  out.gamma = gamma_of(out.gamma_g);
  out.trigger = flag;
  switch (params_.mode) {
    case GovernorMode::pet:
      out.tie_break = tie;
      break;
    case GovernorMode::continuous:
      out.tie_break = tie;
      out.trigger = true;
      break;
    case GovernorMode::none:
    case GovernorMode::planned:  // refused by the constructor
      out.trigger = false;
      break;
  }
  out.cone_count = cones_.size();
  for (int i = 0; i < cones_.size(); ++i) {
    out.margins[static_cast<std::size_t>(i)] = pointing_margin(cones_[i], R_ib);
  }
  return out;
}

GovernorOutput AttitudeGovernor::figures(const Mat3& R_ib, const Vec3& omega_b, const Mat3& R_g,
                                         const Mat3& R_d, bool flag, const TieBreak& tie) const noexcept {
  return figures_into(R_ib, omega_b, R_g, R_d, flag, tie, nullptr);
}

GovernorOutput AttitudeGovernor::figures(const Mat3& R_ib, const Vec3& omega_b, const Mat3& R_g,
                                         const Mat3& R_d, bool flag, const TieBreak& tie,
                                         GovernorMemo& memo) const noexcept {
  return figures_into(R_ib, omega_b, R_g, R_d, flag, tie, &memo);
}

inline void AttitudeGovernor::remember_reference(const Mat3& R_g, GovernorMemo& memo) const noexcept {
  if (memo.has_reference && same_bits(memo.R_g, R_g)) return;
  memo.has_reference = true;
  memo.has_state = false;
  memo.R_g = R_g;
  memo.gamma_g = pointing_threshold(cones_.span(), R_g, params_.gains.kp,
                                    std::span<double>(memo.cosines.data(), static_cast<std::size_t>(cones_.size())));
}

GovernorOutput AttitudeGovernor::evaluate(const Mat3& R_ib, const Vec3& omega_b, const Mat3& R_g,
                                          const Mat3& R_d, bool flag, const TieBreak& tie) const noexcept {
  GovernorOutput out = figures(R_ib, omega_b, R_g, R_d, flag, tie);
  const double decided = params_.robust ? out.W + params_.robust->measurement_margin : out.V;
  switch (params_.mode) {
    case GovernorMode::pet:
      out.rho = held_field(out.R_g, R_d, tie);
      out.xi_g = pet_reference_rate(flag, params_.kappa, out.gamma, decided, out.rho, params_.epsilon);
      break;
    case GovernorMode::continuous:
      out.rho = held_field(out.R_g, R_d, tie);
      out.xi_g = erg_reference_rate(params_.kappa, out.gamma, decided, out.rho, params_.epsilon);
      break;
    case GovernorMode::none:
    case GovernorMode::planned:  // refused by the constructor
      break;
  }
  return out;
}

inline Vec3 AttitudeGovernor::held_field(const Mat3& R_g, const Mat3& R_d, const TieBreak& tie) const noexcept {
  return governor::tie_break_field(tie, cones_.span(), R_g, R_d, navigation_field(R_g, R_d));
}

inline Vec3 AttitudeGovernor::held_field(const Mat3& R_g, const Mat3& R_d, const TieBreak& tie,
                                  std::span<const double> cosines) const noexcept {
  const Vec3 rho = governor::navigation_field(cones_.span(), R_g, R_d, std::min(params_.epsilon, kTieBreakFloorCap),
                                              cosines);
  if (!tie.active) return rho;  // tie_break_field returns ρ_n itself without a held detour
  return governor::tie_break_field(tie, cones_.span(), R_g, R_d, rho);
}

GovernorRates AttitudeGovernor::rates(const Mat3& R_ib, const Vec3& omega_b, const Mat3& R_g, const Mat3& R_d,
                                      bool flag, const TieBreak& tie) const noexcept {
  GovernorMemo memo;  // empty: every figure computed here
  return rates(R_ib, omega_b, R_g, R_d, flag, tie, memo);
}

// flatten: the helpers, ρ_n's terms and Eigen's 3×3 products inline into the integrator's field
// (docs/performance.md, "Shared cone cosines"); inlining leaves every operation and its order as is.
[[gnu::flatten]] GovernorRates AttitudeGovernor::rates(const Mat3& R_ib, const Vec3& omega_b, const Mat3& R_g, const Mat3& R_d,
                                      bool flag, const TieBreak& tie, GovernorMemo& memo) const noexcept {
  GovernorRates out;
  const bool none = params_.mode == GovernorMode::none || params_.mode == GovernorMode::planned;
  const Mat3& R_ref = none ? R_d : R_g;
  // τ and V of figures() at this very state (the monitor's, before the step's first stage).
  const bool known = memo.has_state && same_bits(memo.R_g, R_ref) && same_bits(memo.R_ib, R_ib) &&
                     same_bits(memo.omega_b, omega_b);
  Mat3 R_e;
  if (known) {
    out.tau_b = memo.tau_b;
  } else {
    // RᵀR_g once for τ [PET-ERG eq. (3)] and V, each formed from it as pd_torque and pd_lyapunov do.
    R_e = R_ib.transpose() * R_ref;
    out.tau_b = params_.gains.kp * lie::vee(lie::sk(R_e)) - params_.gains.kd * omega_b;
  }
  // ξ = 0 without a governor and, in mode pet, while the flag of [PET-ERG eq. (5)] is held down.
  if (none || (params_.mode == GovernorMode::pet && !flag)) return out;
  const double V_known = memo.V;  // read before remember_reference may move the memo to R_ref
  remember_reference(R_ref, memo);
  const double gamma = gamma_of(memo.gamma_g);
  const double decided = params_.robust ? decision_level(R_ib, omega_b, R_ref)
                         : known        ? V_known
                                        : 0.5 * omega_b.dot(params_.J * omega_b) + params_.gains.kp * lie::phi(R_e);
  // [PET-ERG eqs. (4), (6)] give ξ = 0 where κ max{Γ − V, 0} is not positive: no ρ_n needed there.
  if (dynamic_safety_margin(params_.kappa, gamma, decided) <= 0.0) return out;
  // The cones' cosines of Γ_g serve ρ_n's repulsive terms at the same R_g.
  const std::span<const double> cosines(memo.cosines.data(), static_cast<std::size_t>(cones_.size()));
  out.xi_g = erg_reference_rate(params_.kappa, gamma, decided, held_field(R_ref, R_d, tie, cosines), params_.epsilon);
  return out;
}

TieBreakUpdate AttitudeGovernor::tie_break_update(const TieBreak& held, const Mat3& R_g,
                                                  const Mat3& R_d) const noexcept {
  if (params_.mode == GovernorMode::none || !params_.saddle_tie_break) return TieBreakUpdate{};
  return update_tie_break(held, cones_.span(), R_g, R_d, std::min(params_.epsilon, kTieBreakFloorCap));
}

void AttitudeGovernor::reset(double t0, const Mat3& R_g0) noexcept {
  started_ = true;
  t_prev_ = t0;
  R_g_ = R_g0;
  last_move_.setZero();
  move_scale_ = 1.0;
  flag_ = params_.mode == GovernorMode::continuous;
  tie_ = TieBreak{};
  clock_ = SamplingClock(t0, params_.Ts);
  out_ = GovernorOutput{};
  out_.R_g = R_g0;
  out_.gamma_d = gamma_d_;
}

Mat3 AttitudeGovernor::bounded_move(const Mat3& R_ib, const Vec3& omega_b, double dt, double scale,
                                    Vec3& applied) const noexcept {
  Vec3 move = dt * out_.xi_g;
  const double length = move.norm();
  // ρ_n of the previous call, the direction of ξ; with robust margins also Δ_max (section 13);
  // times the reversal scale
  const double limit =
      scale * (params_.robust ? std::min(out_.rho.norm(), params_.robust->max_reference_step) : out_.rho.norm());
  if (length > limit) {
    move *= limit / length;
  }
  for (int halving = 0; halving < kMaxMoveHalvings; ++halving) {
    const Mat3 candidate = R_g_ * lie::exp(move);
    if (admissible_move(R_ib, omega_b, candidate)) {
      applied = move;
      return candidate;
    }
    move *= 0.5;
  }
  applied.setZero();
  return R_g_;
}

const GovernorOutput& AttitudeGovernor::step(double t, const Mat3& R_ib, const Vec3& omega_b,
                                             const Mat3& R_d) noexcept {
  if (!started_) {
    reset(t, R_ib);
  }
  if (params_.mode == GovernorMode::none) {
    R_g_ = R_d;
  } else {
    const double dt = t - t_prev_;
    if (dt > 0.0 && out_.xi_g.squaredNorm() > 0.0) {
      if (params_.bounded_step) {
        // A move against the previous one halves the length allowed, a move along it lets the
        // length grow back (×1.25 up to 1): the reference settles at an equilibrium of the field
        // instead of jumping across it (docs/pet-erg.md, "Discrete reference update").
        move_scale_ = last_move_.dot(out_.xi_g) < 0.0 ? 0.5 * move_scale_ : std::min(1.0, 1.25 * move_scale_);
        R_g_ = bounded_move(R_ib, omega_b, dt, move_scale_, last_move_);
      } else {
        const Mat3 candidate = R_g_ * lie::exp(dt * out_.xi_g);
        // Zero-order hold of the rate between calls; keep V ≤ Γ at the call instants.
        if (admissible_move(R_ib, omega_b, candidate)) {
          R_g_ = candidate;
        }
      }
    }
  }
  t_prev_ = std::max(t_prev_, t);
  bool sampled = false;
  bool tie_break_started = false;
  if (params_.mode != GovernorMode::none && clock_.poll(t)) {
    if (params_.mode == GovernorMode::pet) {
      flag_ = trigger_condition(R_ib, omega_b, R_g_);
      sampled = true;
    }
    // The saddle tie-break, at the same instants as (5) and held like its flag (docs/pet-erg.md,
    // section 4, "Saddles: the tie-break"; in mode continuous at the instants k T_s too).
    const TieBreakUpdate u = tie_break_update(tie_, R_g_, R_d);
    tie_ = u.state;
    tie_break_started = u.started;
  }
  out_ = evaluate(R_ib, omega_b, R_g_, R_d, flag_, tie_);
  out_.sampled = sampled;
  out_.tie_break_started = tie_break_started;
  return out_;
}

}  // namespace attiguard::governor
