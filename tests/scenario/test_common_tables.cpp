// scenario/common_tables: one cone schema for pet_erg, mission and reach (same defaults, units
// and messages), the shared header and governor block.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "attiguard/scenario/common_tables.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/read_pet_erg.hpp"
#include "attiguard/scenario/read_reach.hpp"
#include "scenario/scenario_test_support.hpp"

namespace attiguard::scenario {
namespace {

using test::contains;
using test::input_error;

/// A reach scenario with one safety cone of the given keys.
std::string reach_with_cone(const std::string& cone_keys) {
  return R"(kind = "reach"
[system]
model = "free"
inertia = [1.0, 2.0, 3.0]
[initial]
attitude_radius = 0.05
omega_b = [0.0, 0.0, 0.0]
omega_radius = 0.01
[reach]
horizon = 1.0
steps = 10
[[safety.cones]]
axis_b = [0.0, 0.0, 1.0]
direction_i = [0.0, 0.0, 1.0]
)" + cone_keys;
}

/// A pet_erg scenario with one cone of the given keys.
std::string pet_erg_with_cone(const std::string& cone_keys) {
  return R"(kind = "pet_erg"
[body]
inertia = [1.0, 2.0, 3.0]
[control]
kp = 1.0
kd = 2.0
tau_max = 1.0
[desired]
attitude = { quaternion = [1.0, 0.0, 0.0, 0.0] }
[simulation]
duration = 1.0
[[cones]]
axis_b = [0.0, 0.0, 1.0]
direction_i = [0.0, 0.0, 1.0]
)" + cone_keys;
}

TEST(CommonTables, ReachConesTakeTheGovernorConeDefaultsAndUnits) {
  // type defaults to keep_in; half_angle in radians is accepted as in pet_erg.
  const reach::ReachScenario rad = parse_reach(parse_document(reach_with_cone("half_angle = 0.5\n"), "r.toml"));
  ASSERT_EQ(rad.safety.cones.size(), 1U);
  EXPECT_FALSE(rad.safety.cones[0].keep_out);
  EXPECT_EQ(rad.safety.cones[0].half_angle, 0.5);
  EXPECT_EQ(rad.safety.cones[0].name, "cone0");
  const reach::ReachScenario deg = parse_reach(
      parse_document(reach_with_cone("type = \"keep_out\"\nhalf_angle_deg = 30.0\n"), "r.toml"));
  EXPECT_TRUE(deg.safety.cones[0].keep_out);
  EXPECT_NEAR(deg.safety.cones[0].half_angle, std::numbers::pi / 6.0, 1e-15);
}

TEST(CommonTables, ConeErrorsReadTheSameInEveryKind) {
  const std::string both = "half_angle = 0.5\nhalf_angle_deg = 30.0\n";
  const std::string r = input_error([&] { (void)parse_reach(parse_document(reach_with_cone(both), "f.toml")); });
  const std::string p = input_error([&] { (void)parse_pet_erg(parse_document(pet_erg_with_cone(both), "f.toml")); });
  EXPECT_TRUE(contains(r, "half_angle_deg: give either half_angle (rad) or half_angle_deg (degrees), not both"));
  EXPECT_TRUE(contains(p, "half_angle_deg: give either half_angle (rad) or half_angle_deg (degrees), not both"));
  const std::string bad_type = "type = \"keep_near\"\nhalf_angle = 0.5\n";
  const std::string rt = input_error([&] { (void)parse_reach(parse_document(reach_with_cone(bad_type), "f.toml")); });
  const std::string pt = input_error([&] { (void)parse_pet_erg(parse_document(pet_erg_with_cone(bad_type), "f.toml")); });
  EXPECT_EQ(rt.substr(rt.find("type:")), pt.substr(pt.find("type:")));
  // The governor's field keys are not safety-cone keys.
  const std::string field = input_error(
      [&] { (void)parse_reach(parse_document(reach_with_cone("half_angle = 0.5\ndelta_offset = 0.1\n"), "f.toml")); });
  EXPECT_TRUE(contains(field, "delta_offset: unknown key"));
}

TEST(CommonTables, HeaderChecksTheKindAndDefaultsTheNameToTheStem) {
  const Document doc = parse_document("kind = \"pet_erg\"\n", "dir/my_case.toml");
  const TableReader root(doc);
  declare(root, {"kind", "name", "description"});
  EXPECT_EQ(read_header(root, doc, "pet_erg"), "my_case");
  const std::string wrong = input_error([&] { (void)read_header(root, doc, "reach"); });
  EXPECT_TRUE(contains(wrong, "kind: expected \"reach\", got \"pet_erg\""));
}

// A half angle in radians that only makes sense in degrees names the degree key (every kind).
TEST(CommonTables, HalfAngleInDegreesByMistakeNamesHalfAngleDeg) {
  const std::string r = input_error([&] { (void)parse_reach(parse_document(reach_with_cone("half_angle = 40\n"), "f.toml")); });
  const std::string p = input_error([&] { (void)parse_pet_erg(parse_document(pet_erg_with_cone("half_angle = 40\n"), "f.toml")); });
  EXPECT_TRUE(contains(r, "half_angle is in radians; for 40 degrees write half_angle_deg = 40")) << r;
  EXPECT_TRUE(contains(p, "half_angle is in radians; for 40 degrees write half_angle_deg = 40")) << p;
  // A value beyond 360 is no degree either: the plain range message.
  const std::string big = input_error([&] { (void)parse_reach(parse_document(reach_with_cone("half_angle = 400\n"), "f.toml")); });
  EXPECT_FALSE(contains(big, "half_angle_deg = 400")) << big;
}

/// Restores the default work limits when a test ends.
struct DefaultLimitsAfter {
  ~DefaultLimitsAfter() { set_work_limits(WorkLimits{}); }
};

// attitude_cells = omega_cells = 50 (up to 1.6e10 cells) is refused before any work, with the
// count; --max-cells (set_work_limits) raises the limit.
TEST(CommonTables, ReachPartitionBeyondTheCellLimitIsRefusedUntilRaised) {
  const DefaultLimitsAfter restore;
  const std::string text = reach_with_cone("half_angle = 0.5\n") +
                           "[partition]\nattitude_cells = 50\nomega_cells = 50\n";
  const std::string e = input_error([&] { (void)parse_reach(parse_document(text, "f.toml")); });
  EXPECT_TRUE(contains(e, "partition.omega_cells: attitude_cells = 50 and omega_cells = 50 make up "
                          "to 1.5625e+10 cells (attitude_cells^3 x omega_cells^3), 1.5625e+11 "
                          "cell-steps with reach.steps = 10 (at most 1e+05, or raise the limit "
                          "with --max-cells N)")) << e;
  WorkLimits raised;
  raised.reach_cells = 1e12;
  set_work_limits(raised);
  EXPECT_EQ(parse_reach(parse_document(text, "f.toml")).attitude_cells, 50);
}

TEST(CommonTables, StepLimitNamesItsFlagAndCanBeRaised) {
  const DefaultLimitsAfter restore;
  std::string fix = pet_erg_with_cone("half_angle_deg = 120\n");
  fix.replace(fix.find("duration = 1.0\n"), 15, "duration = 1.0\nstep = 1e-9\n");
  const std::string e = input_error([&] { (void)parse_pet_erg(parse_document(fix, "f.toml")); });
  EXPECT_TRUE(contains(e, "simulation.step: needs 1e+09 integrator steps over the duration 1 s "
                          "(step = 1e-09 s; at most 1e+08, or raise the limit with --max-steps N)")) << e;
  WorkLimits raised;
  raised.run_steps = 1e10;
  set_work_limits(raised);
  EXPECT_EQ(parse_pet_erg(parse_document(fix, "f.toml")).integrator.step, 1e-9);
}

}  // namespace
}  // namespace attiguard::scenario
