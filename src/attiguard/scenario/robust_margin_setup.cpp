// The governor's design of a `pet_erg` scenario, located; robust admissibility (docs/pet-erg.md,
// sections 12-13).

#include "attiguard/scenario/robust_margin_setup.hpp"

#include <string>
#include <vector>

#include "attiguard/core/errors.hpp"
#include "attiguard/governor/pointing_threshold.hpp"
#include "attiguard/scenario/messages.hpp"

namespace attiguard::scenario {

governor::GovernorDesign located_design(const TableReader& control, const sim::PetErgScenario& sc) {
  try {
    return sim::design_governor(sc);
  } catch (const SetupError& e) {
    control.fail("margins", e.what());
  }
}

void check_robust_desired(const TableReader& desired, const governor::AttitudeGovernor& gov,
                          const sim::PetErgScenario& sc, const governor::GovernorDesign& design) {
  const governor::RobustMargin& m = *design.params.robust;
  const std::vector<governor::ConeConstraint>& cones = design.cones;
  const std::string key = desired.has("attitude") ? "attitude" : "schedule";
  for (int i = 0; i < sc.desired.size(); ++i) {
    const lie::Mat3& R_d = sc.desired[i].R_d;
    for (std::size_t c = 0; c < cones.size(); ++c) {
      const double cosine = governor::cone_cosine(cones[c], R_d);
      if (cosine < cones[c].zeta) {
        desired.fail(key, "with robust margins this desired attitude lies in the widened repulsive band of cones[" +
                              std::to_string(c) + "] (a_c^T R_d a_b = " + detail::format_number(cosine) + " < zeta = " +
                              detail::format_number(cones[c].zeta) + ", Gamma_min = " + detail::format_number(m.gamma_min) +
                              "): move R_d away from the cone or reduce the imperfections");
      }
    }
    const double G = gov.gamma(R_d);
    if (!(G > m.gamma_min)) {
      desired.fail(key, "with robust margins the reference can never reach this desired attitude: "
                        "Gamma_W(R_d) = " + detail::format_number(G) + " (Gamma_g = " + detail::format_number(gov.gamma_g(R_d)) +
                        ") is not above Gamma_min = " + detail::format_number(m.gamma_min) +
                        ": move R_d away from the cones or reduce the imperfections");
    }
  }
}

std::string robust_initial_problem(const governor::AttitudeGovernor& gov, const sim::PetErgScenario& sc,
                                   const governor::RobustMargin& m) {
  const double G0 = gov.gamma(sc.R_g0);
  // The analysis runs in the frame seen through the attitude bias B (section 13).
  const lie::Mat3 R0_seen = sc.R0_ib * lie::exp(sc.imperfections.sensor.attitude_bias_b);
  const double W0 = gov.level(R0_seen, sc.omega0_b, sc.R_g0) + m.start_allowance;
  if (G0 > m.gamma_min && W0 <= G0) return {};
  return "initial state not admissible with robust margins: W(0) + start allowance = " + detail::format_number(W0) +
         ", Gamma_W(R_g(0)) = " + detail::format_number(G0) + ", Gamma_min = " + detail::format_number(m.gamma_min) +
         " (needs Gamma_min < Gamma_W(R_g(0)) and W(0) + allowance <= Gamma_W(R_g(0)))";
}

}  // namespace attiguard::scenario
