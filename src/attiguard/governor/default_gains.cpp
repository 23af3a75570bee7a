#include "attiguard/governor/default_gains.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "attiguard/core/errors.hpp"
#include "attiguard/core/finite.hpp"
#include "attiguard/governor/torque_threshold.hpp"
#include "attiguard/lie/symmetric_eigen.hpp"

namespace attiguard::governor {

namespace {

void require_default(bool ok, const std::string& what) {
  if (!ok) throw SetupError("governor defaults: " + what);
}

/// Growth of θ_ref per round while the initial kinetic energy exceeds its share of Γ_d.
constexpr double kAngleGrowth = 1.5;
constexpr int kMaxAngleRounds = 80;
/// The integration step is this fraction of the fastest time constant of the closed loop.
constexpr double kStepsPerRate = 0.1;

/// The PD gains of θ_ref (docs/pet-erg.md, section 8): k_p = c_p τ_eff/θ_ref,
/// k_d = 2ζ√(k_p J_d) with J_d = √(J_min J_max), k_p lowered to the flight-loop caps.
void derive_pd_gains(const CraftScales& craft, const GivenGovernorValues& given,
                     const DefaultGainConstants& k, double J_max, double J_min,
                     DerivedGovernorValues& d) {
  const double J_d = damping_inertia(J_min, J_max);
  d.kp = given.kp.value_or(k.stiffness * d.torque_scale / d.reference_angle);
  d.limited_by_control_period = false;
  if (!given.kp && craft.control_period > 0.0) {
    const double h = craft.control_period;
    const double bandwidth_cap = k.bandwidth_period * k.bandwidth_period * J_min / (h * h);
    double cap = bandwidth_cap;
    if (!given.kd) {
      const double root = k.damping_period * J_min / (2.0 * k.damping_ratio * h);
      cap = std::min(cap, root * root / J_d);
    }
    if (d.kp > cap) {
      d.kp = cap;
      d.limited_by_control_period = true;
    }
  }
  d.kd = given.kd.value_or(2.0 * k.damping_ratio * std::sqrt(d.kp * J_d));
}

}  // namespace

double damping_inertia(double J_min, double J_max) noexcept { return std::sqrt(J_min * J_max); }

double effective_torque(const CraftScales& craft) {
  double tau = craft.tau_max;
  if (craft.wheel_torque_radius > 0.0) tau = std::min(tau, craft.wheel_torque_radius);
  tau -= craft.disturbance_bound;
  require_default(positive_finite(tau),
          "the disturbance bound leaves no torque for the PD law (tau_max and the wheels' "
          "inscribed torque minus the disturbance bound must be positive)");
  return tau;
}

DerivedGovernorValues derive_governor_values(const CraftScales& craft,
                                             const GivenGovernorValues& given,
                                             const DefaultGainConstants& k) {
  require_default(craft.J.allFinite(), "the inertia must be finite");
  require_default(positive_finite(craft.tau_max), "tau_max must be positive and finite");
  require_default(std::isfinite(craft.slew_angle) && craft.slew_angle >= 0.0, "the slew angle must be finite");
  require_default(std::isfinite(craft.control_period) && craft.control_period >= 0.0,
          "the control period must be finite and non-negative");
  const double J_min = lie::lambda_min(craft.J);
  const double J_max = lie::lambda_max(craft.J);
  require_default(positive_finite(J_min) && positive_finite(J_max), "the inertia must be positive definite");

  DerivedGovernorValues d;
  d.kp_derived = !given.kp;
  d.kd_derived = !given.kd;
  d.kappa_derived = !given.kappa;
  d.Ts_derived = !given.Ts;
  d.c_gamma_derived = !given.c_gamma;
  d.epsilon_derived = !given.epsilon;
  d.torque_scale = effective_torque(craft);
  require_default(positive_finite(craft.softening), "the softening must be positive and finite");
  d.softening = craft.softening;
  // softening < 1 is a stiffer loop; θ_ref stays above the floor
  d.reference_angle = std::max(std::clamp(craft.slew_angle, k.min_angle, std::numbers::pi) * craft.softening,
                               1e-3 * k.min_angle);

  // θ_ref grows (k_p falls, Γ_d rises) until the initial kinetic energy is at most its share of
  // Γ_d: the initial state is then admissible with room for the reference to move.
  for (int round = 0;; ++round) {
    derive_pd_gains(craft, given, k, J_max, J_min, d);
    d.gamma_d_estimate = compute_torque_threshold({d.kp, d.kd, J_min, d.torque_scale}).gamma_d;
    const bool gains_fixed = given.kp.has_value();
    if (gains_fixed || round >= kMaxAngleRounds ||
        craft.initial_kinetic_energy <= k.energy_share * d.gamma_d_estimate) {
      break;
    }
    d.reference_angle *= kAngleGrowth;
  }
  d.time_scale = std::sqrt(J_max * d.reference_angle / d.torque_scale);
  d.rate_scale = d.reference_angle / d.time_scale;
  d.natural_frequency = std::sqrt(d.kp / J_max);
  d.damping_ratio = d.kd / (2.0 * std::sqrt(d.kp * damping_inertia(J_min, J_max)));
  if (craft.control_period > 0.0) {
    d.bandwidth_period = std::sqrt(d.kp / J_min) * craft.control_period;
    d.damping_period = d.kd * craft.control_period / J_min;
  }
  d.kappa = given.kappa.value_or(k.rate_gain * d.rate_scale / d.gamma_d_estimate);
  double Ts = k.sample_fraction / d.natural_frequency;
  if (craft.control_period > 0.0) {
    Ts = craft.control_period * std::max(1.0, std::round(Ts / craft.control_period));
  }
  d.Ts = given.Ts.value_or(Ts);
  d.c_gamma = given.c_gamma.value_or(k.c_gamma);
  d.epsilon = given.epsilon.value_or(
      std::max(k.epsilon_min, d.kappa * d.gamma_d_estimate / (k.reference_rate_ratio * d.natural_frequency)));
  const double omega_fast = std::max({std::sqrt(d.kp / J_min), d.kd / J_min,
                                     d.kappa * d.gamma_d_estimate / d.epsilon});
  d.integrator_step = std::min(0.5 * d.Ts, kStepsPerRate / omega_fast);
  if (craft.narrowest_band > 0.0) {
    d.integrator_step = std::min(d.integrator_step, kStepsPerRate * craft.narrowest_band / (d.kappa * d.gamma_d_estimate));
  }
  if (craft.control_period > 0.0) d.integrator_step = std::min(d.integrator_step, craft.control_period);
  require_default(positive_finite(d.kp) && positive_finite(d.kd) && positive_finite(d.kappa) &&
              positive_finite(d.Ts) && positive_finite(d.epsilon) &&
              positive_finite(d.integrator_step),
          "the derived gains are not finite (rescale the inertia and the torque limit)");
  return d;
}

}  // namespace attiguard::governor
