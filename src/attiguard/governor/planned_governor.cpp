#include "attiguard/governor/planned_governor.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "attiguard/core/errors.hpp"

namespace attiguard::governor {

double ProgressClock::accel_time() const noexcept {
  if (accel_k > 0.0) return (1.0 - rate_k) / accel_k;
  if (accel_k < 0.0) return rate_k / -accel_k;
  return std::numeric_limits<double>::infinity();
}

double ProgressClock::rate_at(double t) const noexcept {
  return std::clamp(rate_k + accel_k * std::max(0.0, t - t_k), 0.0, 1.0);
}

double ProgressClock::accel_at(double t) const noexcept {
  if (sigma_at(t) >= duration) return 0.0;
  return t - t_k < accel_time() ? accel_k : 0.0;
}

double ProgressClock::sigma_at(double t) const noexcept {
  const double dt = std::max(0.0, t - t_k);
  const double d1 = std::min(dt, accel_time());
  const double rate_end = std::clamp(rate_k + accel_k * d1, 0.0, 1.0);
  const double sigma = sigma_k + rate_k * d1 + 0.5 * accel_k * d1 * d1 + rate_end * (dt - d1);
  return std::min(duration, std::max(sigma_k, sigma));
}

void PlannedGovernor::saturate(const lie::Vec3& law_b, PlannedOutput& o) const noexcept {
  if (params_.slabs.count > 0) {
    // The gauge of the wheels' slabs: the command scaled onto their boundary when beyond it.
    o.demand_ratio = params_.slabs.gauge(law_b);
    o.tau_b = o.demand_ratio > 1.0 ? lie::Vec3(law_b * ((1.0 - 4e-16) / o.demand_ratio)) : law_b;
    return;
  }
  const double norm = law_b.norm();
  o.demand_ratio = norm / params_.tau_max;
  // Scaled a few ulps inside the bound, so that the rounded norm never exceeds τ_max.
  o.tau_b = o.demand_ratio > 1.0 ? lie::Vec3(law_b * ((1.0 - 4e-16) * params_.tau_max / norm)) : law_b;
}

PlannedGovernor::PlannedGovernor(const SlewPlan& plan, std::span<const ConeConstraint> cones,
                                 const PlannedGovernorParams& params)
    : progress_(plan, cones, params.tau_max, params.gains, params.sample_period, params.epsilon),
      params_(params),
      J_inv_b_(plan.inertia().inverse()) {
  if (!(params.control_period >= 0.0) || (params.delay_periods != 0 && params.delay_periods != 1) ||
      (params.delay_periods == 1 && !(params.control_period > 0.0))) {
    throw SetupError("planned governor: control_period must be >= 0 and delay_periods 0 or 1 "
                     "(1 only with a control period)");
  }
  if (params.robust && (!(params.control_period > 0.0) || !(params.robust->rate > 0.0) ||
                        !(params.robust->rate <= 1.0) || !(params.robust->attitude_error >= 0.0) ||
                        !(params.robust->rate_error >= 0.0) || !std::isfinite(params.robust->attitude_error) ||
                        !std::isfinite(params.robust->rate_error))) {
    throw SetupError("planned governor: robust margins need the flight loop (control_period > 0), "
                     "a clock rate in (0, 1] and positive finite error peaks");
  }
}

void PlannedGovernor::predict(const lie::Mat3& R_ib, const lie::Vec3& omega_b, const lie::Vec3& wheel_momentum_b,
                              lie::Mat3& R_next, lie::Vec3& omega_next) const noexcept {
  // One midpoint step of the rigid body under the acting torque (the disturbance unknown), the
  // wheels' momentum held.
  const double h = params_.control_period;
  const lie::Mat3& J = progress_.plan().inertia();
  const lie::Vec3 a1 = J_inv_b_ * (acting_b_ - omega_b.cross(J * omega_b + wheel_momentum_b));
  const lie::Vec3 w_mid = omega_b + 0.5 * h * a1;
  const lie::Vec3 a2 = J_inv_b_ * (acting_b_ - w_mid.cross(J * w_mid + wheel_momentum_b));
  R_next = R_ib * lie::exp(h * w_mid);
  omega_next = omega_b + h * a2;
}

RateChoice PlannedGovernor::robust_choice(double t, double sigma_act, double rate_act, const lie::Mat3& R_ib,
                                          const lie::Vec3& omega_b) const noexcept {
  const PlannedRobust& rb = *params_.robust;
  RateChoice c;
  // From rest at σ = 0 the plan is at rest (ω_p(0) = 0): a jump to the design's ṡ leaves the
  // errors unchanged; afterwards the clock coasts (s̈ = 0), as the design assumed.
  // The measured errors against the reference at t, as a ratio to what the design proved.
  const control::TrackingReference ref = progress_.reference(clock_.sigma_at(t), clock_.rate_at(t), 0.0);
  const control::TrackingError e = control::tracking_error(R_ib, omega_b, ref);
  const bool waiting = sigma_act <= 0.0 && rate_act == 0.0;
  const bool start = waiting && e.e_R.norm() <= rb.gate_attitude && e.e_Omega.norm() <= rb.gate_rate;
  c.rate = start ? rb.rate : rate_act;
  c.accel = 0.0;
  c.rule = start ? RateRule::jump : RateRule::coast;
  c.V = tracking_error_ratio(e, rb.attitude_error + rb.attitude_allowance, rb.rate_error + rb.rate_allowance);
  c.gamma_g = 1.0;
  c.torque_bound = rb.torque_bound;
  c.admissible = c.V <= 1.0;
  return c;
}

void PlannedGovernor::reset(double t0) noexcept {
  out_ = PlannedOutput{};
  acting_b_.setZero();
  pending_b_.setZero();
  clock_ = ProgressClock{t0, 0.0, 0.0, 0.0, progress_.plan().duration()};
  next_sample_ = t0;
  started_ = true;
}

PlannedOutput PlannedGovernor::evaluate(double sigma, double rate, double accel, const lie::Mat3& R_ib,
                                        const lie::Vec3& omega_b) const noexcept {
  PlannedOutput o;
  o.sigma = sigma;
  o.rate = rate;
  o.accel = accel;
  o.reference = progress_.reference(sigma, rate, accel);
  const lie::Mat3& J = progress_.plan().inertia();
  saturate(control::tracking_torque(J, R_ib, omega_b, o.reference, params_.gains), o);
  o.V = control::tracking_lyapunov(J, R_ib, omega_b, o.reference, params_.gains);
  return o;
}

const PlannedOutput& PlannedGovernor::step(double t, const lie::Mat3& R_ib, const lie::Vec3& omega_b,
                                           const lie::Vec3& wheel_momentum_b) noexcept {
  if (!started_) reset(t);
  // With a delay the torque computed now acts from t + h: the state and the clock there.
  const double h = params_.control_period;
  const double t_act = params_.delay_periods == 1 ? t + h : t;
  lie::Mat3 R = R_ib;
  lie::Vec3 omega = omega_b;
  if (params_.delay_periods == 1) {
    acting_b_ = pending_b_;  // computed at the previous instant, acting on [t, t + h)
    predict(R_ib, omega_b, wheel_momentum_b, R, omega);
  }
  RateChoice choice = out_.choice;
  // The plan at the clock's σ, evaluated once: the choice keeps σ at t_act.
  const double sigma = clock_.sigma_at(t_act);
  const SlewPlan& plan = progress_.plan();
  const int k = plan.interval_of(sigma);
  const SlewPlanSample at_sigma = plan.evaluate_in(k, std::min(sigma, plan.duration()));
  // A sampling instant (up to rounding of k·T_s); missed instants are not caught up.
  const bool sampled = t >= next_sample_ - 1e-9 * params_.sample_period;
  if (sampled) {
    choice = params_.robust ? robust_choice(t, sigma, clock_.rate_at(t_act), R_ib, omega_b)
                            : progress_.choose(at_sigma, sigma, R, omega, clock_.rate_at(t_act));
    clock_ = ProgressClock{t_act, sigma, choice.rate, choice.accel, clock_.duration};
    const double Ts = params_.sample_period;
    next_sample_ += Ts * (std::floor((t - next_sample_) / Ts + 1e-9) + 1.0);
  }
  const double rate = clock_.rate_at(t_act);
  const double accel = clock_.accel_at(t_act);
  out_.sigma = sigma;
  out_.rate = rate;
  out_.accel = accel;
  out_.reference = progress_.reference(at_sigma, sigma, rate, accel);
  control::TrackingReference ref = out_.reference;
  if (h > 0.0) {
    // Held over [t_act, t_act + h): the feedforward of the plan's acceleration at the middle.
    const double t_mid = t_act + 0.5 * h;
    const double sigma_mid = clock_.sigma_at(t_mid);
    SlewPlanSample mid;
    const bool same = sigma_mid <= plan.nodes()[static_cast<std::size_t>(k + 1)].t;
    plan.rates_in(same ? k : plan.interval_of(sigma_mid), sigma_mid, mid);
    ref.omega_dot_b = progress_.reference(mid, sigma_mid, clock_.rate_at(t_mid), clock_.accel_at(t_mid))
                          .omega_dot_b;
  }
  const lie::Mat3& J = plan.inertia();
  saturate(control::tracking_torque(J, R, omega, ref, params_.gains) + omega.cross(wheel_momentum_b), out_);
  // V does not depend on s̈: at a sampling instant the choice's V is the V at the rate chosen
  // (with robust margins: the measured errors' ratio to the design's peaks).
  out_.V = sampled ? choice.V : control::tracking_lyapunov(J, R, omega, out_.reference, params_.gains);
  pending_b_ = out_.tau_b;
  out_.choice = choice;
  out_.sampled = sampled;
  return out_;
}

}  // namespace attiguard::governor
