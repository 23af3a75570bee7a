// Guidance defaults derived from the craft (guidance/craft_defaults.hpp, docs/waypoint.md
// "Tuning"): each formula's stated property.
#include <gtest/gtest.h>

#include <cmath>

#include "attiguard/guidance/craft_defaults.hpp"

namespace attiguard::guidance {
namespace {

CraftLimits paper_craft() {
  CraftLimits c;  // Table I of the waypoint paper: 100 kg, 20 N, 0.5 N RCT, J = 20 I, 10 Hz
  return c;
}

TEST(CraftDefaults, CutOffSpeedIsOnePeriodOfThrustAsInThePaperExample) {
  EXPECT_DOUBLE_EQ(craft_main_cutoff_speed(paper_craft(), 100.0), 0.2 * 0.1);  // the paper's 0.02 m/s
  EXPECT_DOUBLE_EQ(craft_main_cutoff_speed(paper_craft(), 0.01), 0.005);      // at most V_d/2
}

TEST(CraftDefaults, PointingToleranceKeepsTheMisalignedThrustWithinHalfAnRct) {
  const CraftLimits c = paper_craft();
  const double alpha = 2.0 * std::asin(craft_pointing_tolerance(c));
  EXPECT_LE(alpha * c.T_max, 0.5 * c.f_max + 1e-12);
  CraftLimits weak = c;
  weak.f_max = 1e-6;  // floor: 2e-3 rad
  EXPECT_NEAR(2.0 * std::asin(craft_pointing_tolerance(weak)), 2e-3, 1e-12);
}

TEST(CraftDefaults, RctGainsPutTheDeadBandsInsideTheAccuracies) {
  const CraftLimits c = paper_craft();
  for (const double dv : {0.001, 0.005, 0.05}) {
    for (const double dp : {0.05, 0.2, 2.0}) {
      const control::RctPositionGains g = craft_rct_gains(c, dv, dp);
      EXPECT_LE(rct_speed_dead_band(c, g, 0.5), 0.5 * dv + 1e-15);
      EXPECT_LE(rct_position_dead_band(c, g, 0.5), 0.5 * dp + 1e-15);
      // The switching line v = λ e is one the RCT can follow from 12.5 δ_p: λ² e ≤ a_rct.
      const double lambda = g.kappa_p / g.kappa_d;
      EXPECT_LE(lambda * lambda * 12.5 * dp, c.a_rct() * (1.0 + 1e-12));
    }
  }
}

TEST(CraftDefaults, ReplanDistanceLeavesRoomForTheRctToStopTheCutOffSpeed) {
  const CraftLimits c = paper_craft();
  const double v = 0.02;
  EXPECT_GE(craft_replan_distance(c, v, 0.2, 0.01, 0.0), 4.0 * rct_stopping_distance(c, v));
  EXPECT_GE(craft_replan_distance(c, v, 0.2, 0.01, 0.0), 25.0 * 0.2);
  // A slew of 100 s: the RCT cover a_rct·100²/4 = 12.5 m by bang-bang meanwhile; twice that.
  EXPECT_DOUBLE_EQ(craft_replan_distance(c, v, 0.2, 0.01, 100.0), 0.5 * c.a_rct() * 1e4);
}

TEST(CraftDefaults, AttitudeGainsRespectTheWheelLimitAndTheSlewTimeFollows) {
  CraftLimits c = paper_craft();
  const control::QuaternionPidGains free = craft_attitude_gains(c);
  EXPECT_NEAR(std::sqrt(free.kp / (2.0 * c.J_max)), 0.3, 1e-12);  // ω_n = 0.3 rad/s at 10 Hz
  EXPECT_NEAR(free.kd, 4.0 * 0.3 * c.J_max, 1e-12);               // ζ = 1
  c.max_wheel_torque = 0.1;
  const control::QuaternionPidGains limited = craft_attitude_gains(c);
  EXPECT_NEAR(limited.kp, c.max_wheel_torque, 1e-12);  // k_p = 2 ω_n² J = τ_w
  EXPECT_DOUBLE_EQ(craft_slew_time(c, limited),
                   std::max(10.0 / std::sqrt(limited.kp / (2.0 * c.J_max)), wheel_half_turn_time(c)));
  EXPECT_NEAR(wheel_half_turn_time(c), 2.0 * std::sqrt(M_PI * 20.0 / 0.1), 1e-9);
}

TEST(CraftDefaults, AttitudeGainsAreShapedByTheInertiaSoEveryAxisHasTheSameBandwidth) {
  CraftLimits c = paper_craft();
  c.J = lie::Vec3(2.0, 5000.0, 5001.0).asDiagonal();  // J_max/J_min = 2500
  c.J_min = 2.0;
  c.J_max = 5001.0;
  const control::QuaternionPidGains g = craft_attitude_gains(c);
  ASSERT_TRUE(g.shaped);
  EXPECT_TRUE(g.shaping.isApprox(c.J / c.J_max, 1e-15));
  EXPECT_DOUBLE_EQ(g.shaping_scale, c.J_max);
  // ω_n = 0.3 rad/s at 10 Hz whatever J_min (the scalar law needed J_min/(4 J_max T_s) = 1e-3).
  EXPECT_NEAR(std::sqrt(g.kp / (2.0 * c.J_max)), 0.3, 1e-12);
  // The sampled derivative term on the lightest axis, k_d S_11 T_s/(2 J_1) = 2 ω_n T_s ≤ 0.2.
  EXPECT_LE(g.kd * g.shaping(0, 0) * c.control_period / (2.0 * c.J(0, 0)), 0.2 + 1e-12);
  EXPECT_NEAR(craft_slew_time(c, g), 10.0 / 0.3, 1e-9);
}

TEST(CraftDefaults, BrakingMarginShrinksWithTheSampledOvershoot) {
  const CraftLimits c = paper_craft();
  EXPECT_DOUBLE_EQ(craft_braking_margin(c, 100.0), 0.95);  // capped
  EXPECT_NEAR(craft_braking_margin(c, 1.0), 1.0 / 1.08, 1e-12);
  EXPECT_DOUBLE_EQ(craft_braking_margin(c, 1e-3), 0.5);    // floor
}

}  // namespace
}  // namespace attiguard::guidance
