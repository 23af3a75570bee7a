// The governor's design of a `pet_erg` run (sim/pet_erg_scenario.hpp, docs/pet-erg.md,
// sections 12-13).

#include "attiguard/sim/pet_erg_scenario.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "attiguard/core/errors.hpp"

namespace attiguard::sim {

governor::GovernorDesignInputs design_inputs(const PetErgScenario& sc) {
  const PetErgImperfections& im = sc.imperfections;
  governor::GovernorDesignInputs in;
  in.params = sc.params;
  in.cones = sc.cones;
  in.wheels = sc.wheels;
  in.control_period = sc.control_period;
  in.margins = sc.margins;
  in.max_reference_step = sc.robust_reference_step;
  in.bounds.disturbance = im.disturbance.bound;
  in.bounds.attitude_bias = im.attitude_bias_bound;
  in.bounds.attitude_noise = im.sensor.attitude_noise;
  in.bounds.rate_bias = im.rate_bias_bound;
  in.bounds.rate_noise = im.sensor.rate_noise;
  in.bounds.delay_periods = im.delay_periods;
  in.bounds.torque_quantum = im.torque_quantum;
  return in;
}

governor::GovernorDesign design_governor(const PetErgScenario& sc) {
  return governor::design(design_inputs(sc));
}

namespace {

/// The largest slew of `sc`: from R_0 through every R_d of the schedule [rad].
double largest_slew(const PetErgScenario& sc) {
  double largest = 0.0;
  lie::Mat3 from = sc.R0_ib;
  for (int i = 0; i < sc.desired.size(); ++i) {
    largest = std::max(largest, lie::log(from.transpose() * sc.desired[i].R_d).norm());
    from = sc.desired[i].R_d;
  }
  return largest;
}

/// min_i u_i/‖r_i‖, the radius of the largest torque ball in the wheel polytope (0 without
/// wheels, or for an array the design refuses).
double wheel_torque_radius(const PetErgScenario& sc) {
  if (sc.wheels.empty()) return 0.0;
  try {
    const dynamics::ReactionWheelArray array(sc.wheels);
    double radius = std::numeric_limits<double>::infinity();
    for (int i = 0; i < array.count(); ++i) {
      radius = std::min(radius, array.wheel(i).torque_max / array.allocation_row(i).norm());
    }
    return std::isfinite(radius) ? radius : 0.0;
  } catch (const SetupError&) {
    return 0.0;
  }
}

}  // namespace

governor::TorqueSlabs wheel_slabs(const PetErgScenario& sc) {
  if (sc.wheels.empty()) return governor::TorqueSlabs{sc.params.tau_max};
  return governor::wheel_torque_slabs(dynamics::ReactionWheelArray(sc.wheels), sc.params.tau_max);
}

governor::CraftScales craft_scales(const PetErgScenario& sc) {
  governor::CraftScales craft;
  craft.J = sc.params.J;
  craft.tau_max = sc.params.tau_max;
  craft.wheel_torque_radius = wheel_torque_radius(sc);
  craft.disturbance_bound = sc.imperfections.disturbance.bound;
  craft.slew_angle = largest_slew(sc);
  craft.initial_kinetic_energy = 0.5 * sc.omega0_b.dot(sc.params.J * sc.omega0_b);
  craft.control_period = sc.control_period;
  for (const governor::ConeConstraint& cone : sc.cones) {
    const double sine = std::sqrt(std::max(0.0, 1.0 - cone.cos_theta_c * cone.cos_theta_c));
    const double band = (cone.zeta - cone.delta) / std::max(sine, 1e-3);
    if (band > 0.0 && (craft.narrowest_band == 0.0 || band < craft.narrowest_band)) craft.narrowest_band = band;
  }
  return craft;
}

governor::DerivedGovernorValues governor_values(const PetErgScenario& sc) {
  governor::GivenGovernorValues given;
  given.kp = sc.params.gains.kp;
  given.kd = sc.params.gains.kd;
  given.kappa = sc.params.kappa;
  given.Ts = sc.params.Ts;
  given.c_gamma = sc.params.c_gamma;
  given.epsilon = sc.params.epsilon;
  governor::CraftScales craft = craft_scales(sc);
  craft.softening = sc.derived.softening > 0.0 ? sc.derived.softening : 1.0;
  governor::DerivedGovernorValues v = governor::derive_governor_values(craft, given);
  const governor::DerivedGovernorValues& d = sc.derived;
  v.kp_derived = d.kp_derived;
  v.kd_derived = d.kd_derived;
  v.kappa_derived = d.kappa_derived;
  v.Ts_derived = d.Ts_derived;
  v.c_gamma_derived = d.c_gamma_derived;
  v.epsilon_derived = d.epsilon_derived;
  v.integrator_step_derived = d.integrator_step_derived;
  if (d.integrator_step_derived) v.integrator_step = sc.integrator.step;
  return v;
}

}  // namespace attiguard::sim
