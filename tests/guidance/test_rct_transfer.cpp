// The RCT transfer of the legs the RCT fly alone (guidance/rct_transfer.hpp; docs/waypoint.md,
// "The RCT-only legs"): its speed profile, and an RCT-only leg of a CubeSat, a large chemical
// craft and an electric tug flown within a stated factor of the analytic bang-bang time
// 2√(d/a), a the RCT's acceleration along the leg — which fine control's law (28) alone misses.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

#include "attiguard/guidance/rct_transfer.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/read_waypoint.hpp"
#include "attiguard/sim/waypoint_run.hpp"
#include "attiguard/sim/waypoint_prediction.hpp"

namespace attiguard::guidance {
namespace {

/// Mission parameters with fine control's switching line (λ = 0.01 1/s) and braking curve.
MissionParams transfer_params() {
  MissionParams p;
  p.mass = 100.0;
  p.f_max = 0.5;  // a_rct = 5e-3 m/s²
  p.cruise_speed = 2.0;
  p.position_accuracy = 0.2;
  p.speed_accuracy = 0.01;
  p.arrival_radius = 0.05;
  p.rct.kappa_d = 1.0;
  p.rct.kappa_p = 0.01;
  p.rct.braking_acceleration = 0.5 * p.f_max / p.mass;
  return p;
}

TEST(RctTransfer, SpeedProfileBrakesWithTheReserveToRestInsideThePositionAccuracy) {
  const MissionParams p = transfer_params();
  const double a = p.f_max / p.mass;
  const double d_s = rct_transfer_stop_distance(p);
  EXPECT_DOUBLE_EQ(d_s, 0.5 * p.position_accuracy);
  // At rest from δ_p/2 in; beyond, the braking curve at (1 − reserve) a: v² = 2 b (d − d_s).
  EXPECT_EQ(rct_transfer_speed(p, d_s, 0.0, 0.1, a), 0.0);
  EXPECT_EQ(rct_transfer_speed(p, 0.1 * d_s, 0.0, 0.1, a), 0.0);
  const double v = rct_transfer_speed(p, d_s + 50.0, 0.0, 0.1, a);
  EXPECT_NEAR(v * v / (2.0 * 50.0), (1.0 - kRctTransferThrustReserve) * a, 1e-12);
  // Moved one control period of flight closer at the closing speed, and capped at V_d.
  EXPECT_LT(rct_transfer_speed(p, d_s + 50.0, 0.5, 0.1, a), v);
  EXPECT_DOUBLE_EQ(rct_transfer_speed(p, 1e6, 0.0, 0.1, a), p.cruise_speed);
  // Along a body diagonal the three thruster pairs give √3 a_rct.
  EXPECT_NEAR(rct_available_acceleration(p, Vec3(1.0, 1.0, 1.0).normalized()), std::sqrt(3.0) * a, 1e-15);
  EXPECT_DOUBLE_EQ(rct_available_acceleration(p, Vec3(0.0, -1.0, 0.0)), a);
  // Hand-over only at rest at the end of the curve: not while far, not while still moving.
  const lie::Mat3 R = lie::Mat3::Identity();
  EXPECT_TRUE(rct_transfer_handover_due(p, R, Vec3(0.5 * d_s, 0.0, 0.0), Vec3::Zero(), 0.1));
  EXPECT_FALSE(rct_transfer_handover_due(p, R, Vec3(0.5 * d_s, 0.0, 0.0), Vec3(0.01, 0.0, 0.0), 0.1));
  EXPECT_FALSE(rct_transfer_handover_due(p, R, Vec3(10.0, 0.0, 0.0), Vec3::Zero(), 0.1));
}

TEST(RctTransfer, ForceTracksTheReferenceVelocityAndNullsTheLateralSpeed) {
  const MissionParams p = transfer_params();
  const lie::Mat3 R = lie::Mat3::Identity();
  const Vec3 e(100.0, 0.0, 0.0);
  const double v_ref = rct_transfer_speed(p, 100.0, 0.0, 0.1, p.f_max / p.mass);
  const Vec3 f = rct_transfer_force(p, R, e, Vec3(0.0, 0.3, 0.0), 0.1);
  EXPECT_NEAR(f.x(), p.mass / 0.1 * v_ref, 1e-9);
  EXPECT_NEAR(f.y(), -p.mass / 0.1 * 0.3, 1e-9);
  EXPECT_EQ(rct_transfer_force(p, R, Vec3::Zero(), Vec3(1.0, 0.0, 0.0), 0.1), Vec3::Zero());
}

/// A one-leg mission from rest at the identity attitude to `waypoint`, a leg inside half the
/// (given) re-plan distance, so that the RCT fly it alone; profile craft otherwise.
struct RctLegCraft {
  const char* name;
  double mass, inertia, main_thrust, rct_thrust, wheel;
  double distance, position_accuracy, speed_accuracy;
};

sim::WaypointScenario rct_leg_scenario(const RctLegCraft& c, bool transfer) {
  const Vec3 wp = c.distance * Vec3(2.0, 1.0, 0.0).normalized();
  const double a = c.rct_thrust / c.mass;
  std::ostringstream s;
  s.precision(17);
  s << "kind = \"waypoint\"\nname = \"" << c.name << "\"\n[spacecraft]\nmass = " << c.mass
    << "\ninertia = [[" << c.inertia << ", 0, 0], [0, " << 0.9 * c.inertia << ", 0], [0, 0, " << 0.7 * c.inertia
    << "]]\nmain_thrust = " << c.main_thrust << "\nrct_thrust = " << c.rct_thrust
    << "\nmax_wheel_torque = " << c.wheel << "\n[[waypoints]]\nposition = [" << wp.x() << ", " << wp.y()
    << ", 0.0]\n[guidance]\ncruise_speed = " << 2.0 * std::sqrt(a * c.distance)
    << "\narrival_radius = " << 0.05 * c.position_accuracy << "\nposition_accuracy = " << c.position_accuracy
    << "\nspeed_accuracy = " << c.speed_accuracy << "\nreplan_distance = " << 3.0 * c.distance
    << "\nrct_transfer = " << (transfer ? "true" : "false") << "\n[simulation]\nduration = "
    << 10.0 * std::sqrt(c.distance / a) + 1000.0 << "\ncontrol_period = 0.1\noutput_interval = 10.0\n";
  return scenario::parse_waypoint(scenario::parse_document(s.str(), std::string(c.name) + ".toml"));
}

// Acceptance of the RCT transfer: an RCT-only leg within 1.2× the bang-bang time 2√(d/a) with
// a = rct_available_acceleration along the leg (the body direction (2, 1, 0)/√5: a = √5/2 a_rct),
// where fine control's law alone (guidance.rct_transfer = false; its braking curve at a_rct/2,
// then its switching line) takes more than 1.25×. Fails if the transfer is removed. Measured:
// 1.140 / 1.424 (CubeSat), 1.059 / 1.296 (large chemical), 1.014 / 1.287 (tug); the rest over
// the bound is the brake reserve, one period of margin and fine control's last slide from δ_p.
// The prediction of the leg is within 10 %.
TEST(RctTransfer, RctOnlyLegsAreFlownNearTheBangBangTime) {
  const RctLegCraft crafts[] = {
      {"cubesat", 4.0, 0.03, 0.1, 0.02, 1e-3, 40.0, 0.2, 0.005},
      {"large_chemical", 6200.0, 8e4, 447.0, 10.5, 1.85, 1000.0, 1.0, 0.01},
      {"electric_tug", 2000.0, 2000.0, 2.0, 0.5, 0.5, 100.0, 0.5, 0.005},
  };
  for (const RctLegCraft& c : crafts) {
    const sim::WaypointScenario with = rct_leg_scenario(c, true);
    const sim::WaypointScenario without = rct_leg_scenario(c, false);
    const double a = rct_available_acceleration(with.mission, Vec3(2.0, 1.0, 0.0).normalized());
    const double bang_bang = 2.0 * std::sqrt(c.distance / a);
    const sim::WaypointSimResult r = sim::simulate_waypoint(with);
    const sim::WaypointSimResult r0 = sim::simulate_waypoint(without);
    ASSERT_TRUE(r.completed && r.finite) << c.name;
    ASSERT_TRUE(r0.completed && r0.finite) << c.name;
    ASSERT_FALSE(r.transitions.empty()) << c.name;
    EXPECT_EQ(r.transitions.front().from, Mode::rct_transfer) << c.name;
    // Handed over inside δ_p below half δ_v, the transfer meets the accuracies itself.
    EXPECT_EQ(r.transitions.front().reason, TransitionReason::accuracy_met) << c.name;
    EXPECT_EQ(r0.transitions.front().from, Mode::fine) << c.name;
    const double predicted = sim::predict_waypoint_mission(with).time;
    std::printf("[ measured ] %-14s RCT-only leg of %.0f m: %.1f s with the transfer, %.1f s by fine control "
                "alone, bang-bang %.1f s (%.3f / %.3f); predicted %.1f s\n",
                c.name, c.distance, r.total_time, r0.total_time, bang_bang, r.total_time / bang_bang,
                r0.total_time / bang_bang, predicted);
    EXPECT_LT(r.total_time, 1.2 * bang_bang) << c.name;
    EXPECT_GT(r0.total_time, 1.25 * bang_bang) << c.name;
    EXPECT_NEAR(r.total_time / predicted, 1.0, 0.1) << c.name;
  }
}

}  // namespace
}  // namespace attiguard::guidance
