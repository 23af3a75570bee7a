/// @file mission_scenario.cpp
/// Parsing of scenario kind `mission` (docs/mission.md).

#include "attiguard/scenario/mission_scenario.hpp"

#include "attiguard/scenario/common_tables.hpp"
#include "attiguard/scenario/document_tree.hpp"
#include "attiguard/scenario/table_reader.hpp"
#include "attiguard/scenario/waypoint_scenario.hpp"

namespace attiguard::scenario {

sim::MissionScenario parse_mission(const Document& doc) {
  sim::MissionScenario sc;
  // The waypoint part: the same document without the governor's keys, read as kind `waypoint`
  // (so its messages and checks are exactly those of the waypoint kind).
  Document wp = doc;
  for (const char* key : {"governor", "control", "erg", "cones"}) root_table(wp).erase(key);
  root_table(wp).insert_or_assign("kind", "waypoint");
  sc.waypoint = parse_waypoint(wp);

  // The governor part: the blocks of kind pet_erg (common_tables.hpp), J from [spacecraft].
  const TableReader root(doc);
  const TableReader control = parse_governor_block(root, sc.params, {"align_tolerance"});
  sc.params.J = sc.waypoint.J;
  sc.align_tolerance = control.number_or("align_tolerance", sc.align_tolerance, NumberRule::positive());
  control.finish();
  sc.cones = parse_cones(root);
  (void)make_governor(root, "control", sc.params, sc.cones);
  return sc;
}

}  // namespace attiguard::scenario
