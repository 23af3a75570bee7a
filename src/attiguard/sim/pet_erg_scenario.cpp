// The governor's design of a `pet_erg` run (sim/pet_erg_scenario.hpp, docs/pet-erg.md,
// sections 12-13).

#include "attiguard/sim/pet_erg_scenario.hpp"

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

}  // namespace attiguard::sim
