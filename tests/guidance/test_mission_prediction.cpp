// The mission-time and Δv prediction of the waypoint guidance (guidance/mission_prediction.hpp;
// docs/waypoint.md, "Prediction"): its reduced slew model against the closed forms of the
// critically damped PD and of the wheel-limited bang-bang slew, its legs against the phase
// formulas, and whole missions against the simulation.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "attiguard/guidance/craft_defaults.hpp"
#include "attiguard/guidance/mission_prediction.hpp"

namespace attiguard::guidance {
namespace {

constexpr double kPiPrediction = std::numbers::pi;

/// A craft profile's PID for J_max = J with wheel limit tau (0 = none) at 10 Hz.
PredictionCraft shaped_craft(double J, double tau) {
  CraftLimits c;
  c.J = lie::Mat3::Identity() * J;
  c.J_max = c.J_min = J;
  c.max_wheel_torque = tau;
  c.control_period = 0.1;
  PredictionCraft p;
  p.J_max = J;
  p.max_wheel_torque = tau;
  p.control_period = 0.1;
  p.gains = craft_attitude_gains(c);
  return p;
}

// Small angles, no wheel limit: J θ̈ = −ω_n² J θ − 2 ω_n J θ̇ (critically damped), so
// θ(t) = θ₀ (1 + ω_n t) e^{−ω_n t}, and the turn ends where sin(θ/2) = tol.
TEST(MissionPrediction, SmallTurnMatchesTheCriticallyDampedClosedForm) {
  for (double J : {0.04, 20.0, 8e4, 5e6}) {
    const PredictionCraft c = shaped_craft(J, 0.0);
    const double omega_n = std::sqrt(c.gains.kp / (2.0 * J));
    const double theta0 = 0.02, tol = 1e-4;
    // (1 + x) e^{−x} = 2 asin(tol)/θ₀ by bisection.
    const double target = 2.0 * std::asin(tol) / theta0;
    double lo = 0.0, hi = 50.0;
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (lo + hi);
      ((1.0 + mid) * std::exp(-mid) > target ? lo : hi) = mid;
    }
    const double expected = lo / omega_n;
    EXPECT_NEAR(predicted_turn_time(c, theta0, tol), expected, 0.02 * expected) << "J = " << J;
  }
}

// With a wheel limit no slew beats the bang-bang 2√(θ J/τ); the craft PID (ω_n ≤ √(τ/(2J)))
// takes at most the 10/ω_n the craft defaults budget for a half turn.
TEST(MissionPrediction, WheelLimitedTurnIsBetweenBangBangAndTheBudget) {
  for (double J : {0.04, 20.0, 8e4, 5e6}) {
    for (double tau : {1e-3 * J, 0.02 * J}) {
      const PredictionCraft c = shaped_craft(J, tau);
      const double t = predicted_turn_time(c, kPiPrediction, 1e-3);
      const double omega_n = std::sqrt(c.gains.kp / (2.0 * J));
      EXPECT_GE(t, 2.0 * std::sqrt(kPiPrediction * J / tau)) << J << " " << tau;
      EXPECT_LE(t, 10.0 / omega_n) << J << " " << tau;
    }
  }
  EXPECT_EQ(predicted_turn_time(shaped_craft(20.0, 1.0), 1e-5, 1e-3), 0.0);  // already pointed
}

MissionParams leg_params() {
  MissionParams p;
  p.mass = 100.0;
  p.T_max = 10.0;  // a = 0.1 m/s²
  p.f_max = 0.5;
  p.cruise_speed = 5.0;
  p.acceleration_fraction = 0.5;
  p.braking_margin = 0.8;
  p.main_cutoff_speed = 0.01;
  p.arrival_radius = 0.05;
  p.position_accuracy = 0.5;
  p.speed_accuracy = 0.01;
  p.replan_distance = 20.0;
  p.brake_speed = 0.1;
  p.flip_lead_time = 30.0;
  p.pointing_tolerance = 1e-3;
  p.rct = {0.01, 0.5, 0.0};
  return p;
}

// One leg from rest, pointed along it: turn-free align, acceleration to V_d, coast, flip,
// braking at γa down to the cut-off, the RCT phase: the phase formulas of docs/waypoint.md.
TEST(MissionPrediction, OneLegIsTheSumOfItsPhases) {
  MissionParams p = leg_params();
  p.brake_speed = 0.05;  // below √(2γaδ) = 0.089 m/s: the hand-over waits for the cut-off speed
  const PredictionCraft c = shaped_craft(20.0, 0.0);
  const Vec3 wp(2000.0, 0.0, 0.0);
  const MissionPrediction pr = predict_mission(p, c, PredictionStart{}, std::span<const Vec3>(&wp, 1));
  ASSERT_EQ(pr.legs.size(), 1u);
  const LegPrediction& l = pr.legs[0];
  const double a = 0.1, g = 0.8, V = 5.0;
  const double t_flip = predicted_turn_time(c, kPiPrediction, p.pointing_tolerance);
  EXPECT_FALSE(l.rct_only);
  EXPECT_DOUBLE_EQ(l.peak_speed, V);  // V_d binds: √(2 a f L) = 20 m/s, the braking point later
  EXPECT_NEAR(l.turn_time, t_flip, 1e-9);
  const double v_h = p.main_cutoff_speed;
  const double d_main = 2000.0 - V * V / (2.0 * a) - V * V / (2.0 * g * a);
  const double t_main = V / a + d_main / V + (V - v_h) / (g * a);
  EXPECT_NEAR(l.time - l.fine_time, t_main, 1e-9 * t_main);
  EXPECT_NEAR(l.delta_v - predicted_fine_phase(p, v_h * v_h / (2.0 * g * a), v_h).delta_v, 2.0 * V - v_h, 1e-9);
  EXPECT_NEAR(pr.time, l.time, 0.0);
}

// A leg inside half the re-plan distance is the RCT's (start_leg), and one met at the start
// (within δ_p, slower than δ_v) takes no time.
TEST(MissionPrediction, ShortLegsAreTheRctsAndAMetLegTakesNoTime) {
  const MissionParams p = leg_params();
  const PredictionCraft c = shaped_craft(20.0, 0.0);
  const Vec3 wps[] = {Vec3(8.0, 0.0, 0.0), Vec3(8.2, 0.0, 0.0)};
  const MissionPrediction pr = predict_mission(p, c, PredictionStart{}, wps);
  ASSERT_EQ(pr.legs.size(), 2u);
  EXPECT_TRUE(pr.legs[0].rct_only);
  EXPECT_GT(pr.legs[0].time, 2.0 * std::sqrt(8.0 / (p.f_max / p.mass)));  // slower than RCT bang-bang
  EXPECT_EQ(pr.legs[1].time, 0.0);
  EXPECT_EQ(pr.legs[1].delta_v, 0.0);
}

// The RCT phase with the braking curve: accelerate to √(2 b e), follow it at b, then the line
// v = λ e; without the curve (b = 0) a leg beyond the line's reach is predicted as the line's.
TEST(MissionPrediction, FinePhaseFollowsTheBrakingCurveThenTheLine) {
  MissionParams p = leg_params();
  p.rct.braking_acceleration = 0.5 * p.f_max / p.mass;  // 2.5e-3; 2b/λ² = 12.5 m (λ = 0.02)
  const double a = p.f_max / p.mass, b = p.rct.braking_acceleration, lambda = 0.02;
  const FinePhase f = predicted_fine_phase(p, 1000.0, 0.0);
  const double e_c = 2.0 * a * 1000.0 / (2.0 * (a + b));
  const double v_c = std::sqrt(2.0 * b * e_c), e_x = 2.0 * b / (lambda * lambda), v_x = lambda * e_x;
  const double e_end = std::min(p.position_accuracy, p.speed_accuracy / lambda);
  EXPECT_NEAR(f.time, v_c / a + (v_c - v_x) / b + std::log(e_x / e_end) / lambda, 1e-9);
  EXPECT_NEAR(f.delta_v, 2.0 * v_c, 1e-12);
  // Bang-bang is the floor.
  EXPECT_GT(f.time, 2.0 * std::sqrt(1000.0 / a));
}

}  // namespace
}  // namespace attiguard::guidance
