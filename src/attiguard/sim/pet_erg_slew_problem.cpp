#include "attiguard/sim/pet_erg_slew_problem.hpp"

#include "attiguard/core/errors.hpp"
#include "attiguard/governor/default_gains.hpp"

namespace attiguard::sim {

std::optional<SlewRefusal> slew_refusal(const PetErgScenario& sc, SlewStart start) {
  if (sc.desired.size() != 1) {
    return SlewRefusal{"desired", "schedule",
                       "the planner plans one rest-to-rest slew; this schedule has " +
                           std::to_string(sc.desired.size()) + " attitudes"};
  }
  if (start == SlewStart::at_rest && sc.omega0_b.norm() > 0.0) {
    return SlewRefusal{"initial", "omega_b",
                       "the planner plans a rest-to-rest slew: the initial rate must be zero"};
  }
  if (lie::log(sc.R0_ib.transpose() * sc.desired.final_attitude()).norm() < 1e-9) {
    return SlewRefusal{"desired", "attitude",
                       "the desired attitude is the initial one: there is no slew to plan"};
  }
  return std::nullopt;
}

plan::SlewProblem slew_problem(const PetErgScenario& sc, SlewStart start) {
  if (const auto refusal = slew_refusal(sc, start)) {
    throw SetupError(refusal->table + "." + refusal->key + ": " + refusal->message);
  }
  plan::SlewProblem p;
  p.J_b = sc.params.J;
  p.R_start = sc.R0_ib;
  p.R_target = sc.desired.final_attitude();
  p.tau_max = governor::effective_torque(craft_scales(sc));
  p.cones = sc.cones;
  p.torque_headroom = sc.plan.torque_headroom;
  p.cone_margin = sc.plan.cone_margin;
  return p;
}

plan::PlannerOptions planner_options(const PetErgScenario& sc) {
  plan::PlannerOptions o;
  o.intervals = sc.plan.intervals;
  return o;
}

}  // namespace attiguard::sim
