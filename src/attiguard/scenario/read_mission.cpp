/// @file read_mission.cpp
/// Parsing of scenario kind `mission` (docs/mission.md).

#include "attiguard/scenario/read_mission.hpp"

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "attiguard/core/four_digits.hpp"
#include "attiguard/guidance/leg_attitudes.hpp"

#include "attiguard/scenario/common_tables.hpp"
#include "attiguard/scenario/document_tree.hpp"
#include "attiguard/scenario/table_reader.hpp"
#include "attiguard/scenario/read_waypoint.hpp"
#include "attiguard/scenario/resolved_scenario.hpp"
#include "attiguard/sim/mission_kind_prediction.hpp"

namespace attiguard::scenario {

namespace {

/// Rejects a mission whose predicted steady desired attitude (guidance/leg_attitudes.hpp) violates
/// a cone or lies in its repulsive band (c < ζ, PET-ERG paper's navigation field): the governed
/// reference could never converge to it, so the flight would stall (as kind pet_erg rejects such
/// an R_d). Reported at the waypoint's position.
void check_leg_attitudes(const TableReader& root, const sim::MissionScenario& sc) {
  const sim::WaypointScenario& w = sc.waypoint;
  const std::vector<guidance::LegAttitude> legs = guidance::nominal_leg_attitudes(
      w.R0_ib, w.p0_i, w.waypoints_i, std::max(w.mission.arrival_radius, 0.5 * w.mission.replan_distance));
  if (legs.empty() || sc.cones.empty()) return;
  const std::vector<TableReader> wps = root.array_of_tables("waypoints");
  for (const guidance::LegAttitude& leg : legs) {
    for (std::size_t i = 0; i < sc.cones.size(); ++i) {
      const governor::ConeConstraint& cone = sc.cones[i];
      const double c = governor::cone_cosine(cone, leg.R_id);
      if (c < cone.zeta) {
        wps[static_cast<std::size_t>(leg.waypoint)].fail(
            "position", std::string("the desired attitude of leg ") + std::to_string(leg.waypoint) +
                            (leg.braking ? " while braking (x_b away from the waypoint)"
                                         : " (x_b towards the waypoint)") +
                            " lies " + (c < cone.cos_theta_c ? "inside" : "in the repulsive band of") +
                            " cones[" + std::to_string(i) + "] (a_c^T R_d a_b = " + four_digits(c) +
                            " < zeta = " + four_digits(cone.zeta) +
                            "): the governed attitude cannot reach it; move the waypoint or the cone");
      }
    }
  }
}

/// [guidance] flip_lead_time when the file leaves it out (docs/mission.md, "Prediction"): 1.5
/// times the longest predicted flip of the nominal legs (guidance/leg_attitudes.hpp) flown by
/// the mission's own attitude loop (sim::predicted_governed_turn), instead of the waypoint kind's
/// PID slew, which the mission does not fly. Unchanged when no leg has a flip or a flip does not
/// converge within the duration (the prediction then warns).
void derive_flip_lead_time(const TableReader& root, sim::MissionScenario& sc) {
  sim::WaypointScenario& w = sc.waypoint;
  if (root.table_or_empty("guidance").has("flip_lead_time")) return;
  const std::vector<guidance::LegAttitude> legs = guidance::nominal_leg_attitudes(
      w.R0_ib, w.p0_i, w.waypoints_i, std::max(w.mission.arrival_radius, 0.5 * w.mission.replan_distance));
  double longest = 0.0;
  for (std::size_t k = 0; k + 1 < legs.size(); k += 2) {
    const sim::PredictedTurn flip = sim::predicted_governed_turn(sc, sc.params.mode, legs[k].R_id, legs[k + 1].R_id);
    if (!flip.converged) return;
    longest = std::max(longest, flip.time);
  }
  if (longest > 0.0) {
    w.mission.flip_lead_time = 1.5 * longest;
    DefaultsRecorder::replace_derived("guidance.flip_lead_time", w.mission.flip_lead_time);  // scenario.resolved.toml
  }
}

}  // namespace

sim::MissionScenario parse_mission(const Document& doc) {
  sim::MissionScenario sc;
  // The waypoint part, read in place by the waypoint kind's reader (so its messages, with their
  // FILE:LINE:COL, and its checks are exactly those of the waypoint kind); the governor's keys
  // are read below.
  sc.waypoint = parse_waypoint_part(doc, "mission", {"governor", "control", "erg", "cones"});

  // The governor part: the blocks of kind pet_erg (common_tables.hpp), J from [spacecraft].
  const TableReader root(doc);
  const TableReader control = parse_governor_block(root, sc.params, {"align_tolerance"});
  // governor = "planned" plans each slew at its start (docs/mission.md, "Planned slews"); the
  // PET-ERG's [erg] has no meaning there.
  const bool planned = sc.params.mode == governor::GovernorMode::planned;
  if (planned && root.has("erg")) {
    root.fail("erg", "[erg] sets the PET-ERG's reference governor; governor = \"planned\" does not "
                     "use it (remove it, or set governor = \"pet\")");
  }
  sc.params.J = sc.waypoint.J;
  sc.align_tolerance = control.number_or("align_tolerance", sc.align_tolerance, NumberRule::positive());
  control.finish();
  sc.cones = parse_cones(root);
  // The planned mode's hold between slews is the PD law's: its limits and cones are validated as
  // mode none's (as kind pet_erg does for its planned mode).
  governor::GovernorParams validated = sc.params;
  if (planned) validated.mode = governor::GovernorMode::none;
  (void)make_governor(root, "control", validated, sc.cones);
  check_leg_attitudes(root, sc);
  derive_flip_lead_time(root, sc);
  return sc;
}

}  // namespace attiguard::scenario
