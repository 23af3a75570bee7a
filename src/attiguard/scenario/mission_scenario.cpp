/// @file mission_scenario.cpp
/// Parsing of scenario kind `mission` (docs/mission.md).

#include "attiguard/scenario/mission_scenario.hpp"

#include <array>
#include <string>
#include <string_view>

#include "attiguard/scenario/pet_erg_scenario.hpp"
#include "attiguard/scenario/table_reader.hpp"

namespace attiguard::scenario {

MissionScenario parse_mission(const Document& doc) {
  MissionScenario sc;
  // The waypoint part: the same document without the governor's keys, read as kind `waypoint`
  // (so its messages and checks are exactly those of the waypoint kind).
  Document wp{doc.path, doc.root};
  for (const char* key : {"governor", "control", "erg", "cones"}) wp.root.erase(key);
  wp.root.insert_or_assign("kind", "waypoint");
  sc.waypoint = parse_waypoint(wp);

  const TableReader root(doc);
  static constexpr std::array<std::string_view, 3> modes{"pet", "continuous", "none"};
  const std::string mode = root.string_or("governor", "pet", modes);
  sc.params.mode = mode == "pet"          ? governor::GovernorMode::pet
                   : mode == "continuous" ? governor::GovernorMode::continuous
                                          : governor::GovernorMode::none;
  sc.params.J = sc.waypoint.J;

  const TableReader control = root.table("control");
  for (const char* key : {"kp", "kd", "tau_max", "align_tolerance"}) (void)control.has(key);
  sc.params.gains.kp = control.number("kp", NumberRule::positive());
  sc.params.gains.kd = control.number("kd", NumberRule::positive());
  sc.params.tau_max = control.number("tau_max", NumberRule::positive());
  sc.align_tolerance = control.number_or("align_tolerance", sc.align_tolerance, NumberRule::positive());
  control.finish();

  parse_erg_table(root, sc.params);

  if (root.has("cones")) {
    const std::vector<TableReader> cones = root.array_of_tables("cones");
    if (cones.size() > static_cast<std::size_t>(governor::kMaxCones)) {
      root.fail("cones", "at most " + std::to_string(governor::kMaxCones) + " cone constraints");
    }
    for (const TableReader& c : cones) {
      sc.cones.push_back(parse_cone(c));
      c.finish();
    }
  }
  // The governor's own validation (Γ_d, cones) with the scenario's messages.
  try {
    (void)governor::AttitudeGovernor(sc.params, sc.cones);
  } catch (const std::invalid_argument& e) {
    root.fail("control", e.what());
  }
  return sc;
}

}  // namespace attiguard::scenario
