#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "attiguard/scenario/dispersion.hpp"
#include "attiguard/scenario/key_path.hpp"
#include "attiguard/campaign/seed.hpp"
#include "attiguard/core/errors.hpp"
#include "attiguard/dynamics/rigid_body.hpp"
#include "attiguard/lie/quaternion.hpp"
#include "attiguard/lie/so3.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/document_tree.hpp"

namespace attiguard::scenario {
namespace {

constexpr const char* kBase = R"(
kind = "rigid_body"
[body]
inertia = [1.0, 2.0, 3.0]
[initial]
attitude = { axis = [0.0, 0.0, 1.0], angle_deg = 40.0 }
omega_b = [0.2, 0.3, 0.4]
[control]
kp = 5.0
[[cones]]
direction_i = [0.0, 0.0, 1.0]
)";

scenario::Document doc_with(const std::string& dispersions) {
  return scenario::parse_document(std::string(kBase) + "[dispersions]\n" + dispersions, "t.toml");
}

TEST(CampaignDispersion, NumberStaysInBoundsAndIsWritten) {
  const auto doc = doc_with(R"("control.kp" = { distribution = "truncated_normal", sigma = 1.0, delta = 0.5 })");
  const DispersionPlan plan = read_dispersions(doc);
  const auto nominal = nominal_document(doc);
  EXPECT_FALSE(nominal.has_top_level("dispersions"));
  ASSERT_EQ(dispersion_columns(plan), std::vector<std::string>{"control.kp"});
  campaign::Rng rng(3);
  for (int i = 0; i < 1000; ++i) {
    Document out = nominal;
    std::vector<double> values;
    apply_dispersions(plan, nominal, rng, out, values);
    ASSERT_EQ(values.size(), 1u);
    EXPECT_GE(values[0], 4.5);
    EXPECT_LE(values[0], 5.5);
    EXPECT_EQ(*resolve_key_path(root_table(out), "control.kp")->value<double>(), values[0]);
  }
}

TEST(CampaignDispersion, InertiaStaysPhysical) {
  const auto doc = doc_with(
      R"("body.inertia" = { type = "inertia", moments_rel_sigma = 0.3, axes_max_angle_deg = 90 })");
  const DispersionPlan plan = read_dispersions(doc);
  const auto nominal = nominal_document(doc);
  campaign::Rng rng(4);
  for (int i = 0; i < 2000; ++i) {
    Document out = nominal;
    std::vector<double> v;
    apply_dispersions(plan, nominal, rng, out, v);
    ASSERT_EQ(v.size(), 6u);
    lie::Mat3 J;
    J << v[0], v[3], v[4], v[3], v[1], v[5], v[4], v[5], v[2];
    EXPECT_FALSE(dynamics::inertia_error(J).has_value()) << *dynamics::inertia_error(J);
  }
}

TEST(CampaignDispersion, AttitudeBallAndDirectionCap) {
  const auto doc = doc_with(R"(
"initial.attitude" = { type = "attitude", mode = "ball", max_angle_deg = 10 }
"cones[0].direction_i" = { type = "direction", half_angle_deg = 3 }
)");
  const DispersionPlan plan = read_dispersions(doc);
  const auto nominal = nominal_document(doc);
  const lie::Mat3 R0 = lie::exp(lie::Vec3(0, 0, 40.0 * std::numbers::pi / 180.0));
  campaign::Rng rng(5);
  for (int i = 0; i < 2000; ++i) {
    Document out = nominal;
    std::vector<double> v;
    apply_dispersions(plan, nominal, rng, out, v);
    ASSERT_EQ(v.size(), 7u);  // cones[0].direction_i (xyz) then initial.attitude (q): sorted keys
    const lie::Vec3 n(v[0], v[1], v[2]);
    EXPECT_NEAR(n.norm(), 1.0, 1e-12);
    EXPECT_LE(std::acos(std::min(1.0, n.z())), 3.0 * std::numbers::pi / 180.0 + 1e-9);
    const lie::Mat3 R = lie::quat_to_rotation(lie::Quat(v[3], v[4], v[5], v[6]));
    EXPECT_LE(lie::log(R0.transpose() * R).norm(), 10.0 * std::numbers::pi / 180.0 + 1e-9);
  }
}

TEST(CampaignDispersion, UniformAttitudeCoversSO3) {
  const auto doc = doc_with(R"("initial.attitude" = { type = "attitude", mode = "uniform" })");
  const DispersionPlan plan = read_dispersions(doc);
  const auto nominal = nominal_document(doc);
  campaign::Rng rng(6);
  double mean_trace = 0.0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    Document out = nominal;
    std::vector<double> v;
    apply_dispersions(plan, nominal, rng, out, v);
    mean_trace += lie::quat_to_rotation(lie::Quat(v[0], v[1], v[2], v[3])).trace();
  }
  EXPECT_NEAR(mean_trace / n, 0.0, 0.03);  // E[tr R] = 0 under the Haar measure
}

TEST(CampaignDispersion, BadEntriesAreLocatedInputErrors) {
  auto message = [](const std::string& d) {
    try {
      (void)read_dispersions(doc_with(d));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message(R"("control.kq" = { distribution = "uniform", min = 1, max = 2 })")
                .find("no value at key path 'control.kq'"),
            std::string::npos);
  EXPECT_NE(message(R"("control.kp" = { distribution = "uniform" })").find("needs 'min' and 'max'"),
            std::string::npos);
  EXPECT_NE(message(R"("control.kp" = { distribution = "gauss", sigma = 1 })").find("distribution"),
            std::string::npos);
  EXPECT_NE(message(R"("control.kp" = { distribution = "normal", sigma = 1, sigmaa = 2 })")
                .find("sigmaa"),
            std::string::npos);
  EXPECT_NE(message(R"("control.kp" = { type = "direction", half_angle_deg = 2 })")
                .find("not a 3-vector"),
            std::string::npos);
  EXPECT_NE(message("").find("at least one"), std::string::npos);
}

// A wide truncated normal that can be sampled spreads over its bounds (it used to return the
// nominal whenever 10^4 draws missed: "exactly the nominal 200 times out of 200" for σ = 1e6);
// one whose mass inside is below 1e-3 is refused with the numbers.
TEST(CampaignDispersion, TruncatedNormalIsSampledOrRefusedNeverClamped) {
  const auto doc = doc_with(
      R"("control.kp" = { distribution = "truncated_normal", sigma = 100.0, min = 0.1, max = 1.0 })");
  const DispersionPlan plan = read_dispersions(doc);
  const auto nominal = nominal_document(doc);
  campaign::Rng rng(5);
  double lo = 1.0, hi = 0.0;
  for (int i = 0; i < 200; ++i) {
    Document out = nominal;
    std::vector<double> values;
    apply_dispersions(plan, nominal, rng, out, values);
    ASSERT_GE(values[0], 0.1);
    ASSERT_LE(values[0], 1.0);
    lo = std::min(lo, values[0]);
    hi = std::max(hi, values[0]);
  }
  EXPECT_LT(lo, 0.2);
  EXPECT_GT(hi, 0.9);
  const auto refused = doc_with(
      R"("control.kp" = { distribution = "truncated_normal", sigma = 1e6, min = 0.1, max = 1.0 })");
  try {
    (void)read_dispersions(refused);
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("has a mass of 3.59e-07 inside [0.1, 1] (at least 0.001"),
              std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace attiguard::scenario

namespace attiguard::scenario {
namespace {

/// A waypoint scenario starting at [initial] position p0 with two waypoints, and `dispersions`.
scenario::Document waypoint_doc_with(const std::string& dispersions) {
  const std::string text = R"(
kind = "waypoint"
[spacecraft]
mass = 100.0
inertia = [20.0, 20.0, 20.0]
main_thrust = 20.0
rct_thrust = 0.5
[initial]
position = [10.0, -20.0, 30.0]
[[waypoints]]
position = [100.0, 0.0, 0.0]
[[waypoints]]
position = [100.0, 100.0, 0.0]
[guidance]
cruise_speed = 5.0
arrival_radius = 0.1
position_accuracy = 0.5
speed_accuracy = 0.01
[simulation]
duration = 5000.0
[dispersions]
)";
  return scenario::parse_document(text + dispersions, "w.toml");
}

// docs/campaigns.md, "[dispersions]", type waypoints: count, leg lengths and turns in their
// ranges, from [initial] position; columns fixed by count_max (0 beyond the count); the
// scenario's list replaced; the same seed gives the same list.
TEST(CampaignDispersion, WaypointListsKeepTheirCountLegsAndTurns) {
  const auto doc = waypoint_doc_with(
      R"("waypoints" = { type = "waypoints", count_min = 2, count_max = 4, leg_min = 20.0, leg_max = 5e4, turn_max_deg = 30 })");
  const DispersionPlan plan = read_dispersions(doc);
  const auto nominal = nominal_document(doc);
  const std::vector<std::string> cols = dispersion_columns(plan);
  ASSERT_EQ(cols.size(), 13u);
  EXPECT_EQ(cols[0], "waypoints.count");
  EXPECT_EQ(cols[1], "waypoints[0].x");
  EXPECT_EQ(cols[12], "waypoints[3].z");
  campaign::Rng rng(11);
  std::array<int, 5> counts{};
  double shortest = 1e300, longest = 0.0, widest_turn = 0.0;
  for (int i = 0; i < 2000; ++i) {
    Document out = nominal;
    std::vector<double> values;
    apply_dispersions(plan, nominal, rng, out, values);
    ASSERT_EQ(values.size(), 13u);
    const int n = static_cast<int>(values[0]);
    ASSERT_GE(n, 2);
    ASSERT_LE(n, 4);
    ++counts[static_cast<std::size_t>(n)];
    const toml::array* list = resolve_key_path(root_table(out), "waypoints")->as_array();
    ASSERT_EQ(static_cast<int>(list->size()), n);
    lie::Vec3 from(10.0, -20.0, 30.0), dir_prev = lie::Vec3::Zero();
    for (int k = 0; k < 4; ++k) {
      const lie::Vec3 p(values[1 + 3 * k], values[2 + 3 * k], values[3 + 3 * k]);
      if (k >= n) {
        EXPECT_EQ(p.norm(), 0.0);
        continue;
      }
      const toml::array& pos = *list->get(static_cast<std::size_t>(k))->as_table()->get("position")->as_array();
      EXPECT_EQ(pos.get(0)->value<double>(), p(0));
      const double leg = (p - from).norm();
      shortest = std::min(shortest, leg);
      longest = std::max(longest, leg);
      EXPECT_GE(leg, 20.0 * (1.0 - 1e-12));
      EXPECT_LE(leg, 5e4 * (1.0 + 1e-12));
      const lie::Vec3 dir = (p - from) / leg;
      if (k > 0) widest_turn = std::max(widest_turn, std::acos(std::clamp(dir.dot(dir_prev), -1.0, 1.0)));
      dir_prev = dir;
      from = p;
    }
  }
  EXPECT_GT(counts[2], 500);  // uniform over 2, 3, 4
  EXPECT_GT(counts[4], 500);
  EXPECT_LT(shortest, 30.0);  // log-uniform reaches both ends
  EXPECT_GT(longest, 3e4);
  EXPECT_LE(widest_turn, 30.0 * std::numbers::pi / 180.0 + 1e-9);
  EXPECT_GT(widest_turn, 25.0 * std::numbers::pi / 180.0);
  // Deterministic per seed.
  campaign::Rng a(5), b(5);
  Document out_a = nominal, out_b = nominal;
  std::vector<double> va, vb;
  apply_dispersions(plan, nominal, a, out_a, va);
  apply_dispersions(plan, nominal, b, out_b, vb);
  EXPECT_EQ(va, vb);
}

TEST(CampaignDispersion, WaypointListRefusalsNameTheField) {
  auto message = [](const std::string& entry) {
    try {
      (void)read_dispersions(waypoint_doc_with(entry));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message(R"("waypoints" = { type = "waypoints", count_min = 3, count_max = 2, leg_min = 1.0, leg_max = 2.0 })")
                .find("count_max: must be >= count_min (3)"), std::string::npos);
  EXPECT_NE(message(R"("waypoints" = { type = "waypoints", count_max = 65, leg_min = 1.0, leg_max = 2.0 })")
                .find("count_max"), std::string::npos);
  EXPECT_NE(message(R"("waypoints" = { type = "waypoints", leg_min = 3.0, leg_max = 2.0 })")
                .find("leg_max: must be >= leg_min (3)"), std::string::npos);
  EXPECT_NE(message(R"("waypoints" = { type = "waypoints", leg_min = 0.0, leg_max = 2.0 })").find("leg_min"),
            std::string::npos);
  EXPECT_NE(message(R"("waypoints" = { type = "waypoints", leg_min = 1.0, leg_max = 2e14 })").find("leg_max"),
            std::string::npos);
  EXPECT_NE(message(R"("waypoints" = { type = "waypoints", leg_min = 1.0, leg_max = 2.0, turn_max_deg = 0 })")
                .find("turn_max_deg"), std::string::npos);
  EXPECT_NE(message(R"("waypoints" = { type = "waypoints", leg_min = 1.0 })").find("leg_max"), std::string::npos);
  EXPECT_NE(message(R"("waypoints" = { type = "waypoints", leg_min = 1.0, leg_max = 2.0, legs = 3 })").find("legs"),
            std::string::npos);
  EXPECT_NE(message(R"("waypoints[0].position" = { type = "waypoints", leg_min = 1.0, leg_max = 2.0 })")
                .find("is not the scenario's [[waypoints]]"), std::string::npos);
  EXPECT_EQ(message(R"("waypoints" = { type = "waypoints", leg_min = 1.0, leg_max = 2.0 })"), "accepted");
}

}  // namespace
}  // namespace attiguard::scenario
