// The wheels' torque set of the robust planned mode (governor/torque_slabs.hpp; docs/pet-erg.md,
// section 16.3, "Wheels"): the gauge puts a torque on the boundary of what the pseudo-inverse
// allocation applies unclipped; the inflated gauge is the worst over the error ball, attained;
// the plan's gauge is the largest along the plan; the planned governor saturates onto the slabs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "attiguard/dynamics/reaction_wheel_array.hpp"
#include "attiguard/governor/cone_constraint.hpp"
#include "attiguard/governor/planned_governor.hpp"
#include "attiguard/governor/torque_slabs.hpp"
#include "attiguard/lie/so3.hpp"
#include "attiguard/plan/slew_planner.hpp"

namespace attiguard::governor::torque_slabs_test {
namespace {

using lie::Mat3;
using lie::Vec3;

constexpr double kDeg = std::numbers::pi / 180.0;

/// A 4-wheel pyramid at 35.26 deg (the robust campaign's) of `u` N m per wheel, and a skewed
/// 3-wheel array with unequal limits.
std::vector<dynamics::ReactionWheelArray> arrays() {
  const auto pyramid = dynamics::pyramid_wheels(std::atan(1.0 / std::sqrt(2.0)), 0.1, 6.0);
  const std::array<dynamics::ReactionWheel, 3> skew{
      dynamics::ReactionWheel{Vec3(1.0, 0.2, 0.0).normalized(), 2e-3, 0.01, 0.0},
      dynamics::ReactionWheel{Vec3(0.0, 1.0, 0.3).normalized(), 1e-3, 0.01, 0.0},
      dynamics::ReactionWheel{Vec3(0.1, 0.0, 1.0).normalized(), 5e-4, 0.01, 0.0}};
  return {dynamics::ReactionWheelArray(pyramid), dynamics::ReactionWheelArray(skew)};
}

Vec3 random_unit(std::mt19937& rng) {
  std::normal_distribution<double> n;
  return Vec3(n(rng), n(rng), n(rng)).normalized();
}

TEST(TorqueSlabs, WithoutSlabsTheGaugeIsTheNormOverTauMax) {
  TorqueSlabs ball;
  ball.ball = 0.25;
  const Vec3 tau(0.1, -0.2, 0.05);
  EXPECT_DOUBLE_EQ(ball.gauge(tau), tau.norm() / 0.25);
  EXPECT_DOUBLE_EQ(ball.inflated_gauge(tau, 0.01), (tau.norm() + 0.01) / 0.25);
}

TEST(TorqueSlabs, APyramidGivesFourTimesTheSineOfItsElevationAboutItsAxis) {
  // Every wheel of a pyramid at elevation e adds u sin e about z: 4 u sin e.
  for (const double e : {0.3, std::atan(1.0 / std::sqrt(2.0)), 1.1}) {
    const dynamics::ReactionWheelArray array(dynamics::pyramid_wheels(e, 0.1, 6.0));
    const TorqueSlabs s = wheel_torque_slabs(array, 100.0);
    EXPECT_NEAR(s.torque_along(Vec3::UnitZ()), 4.0 * 0.1 * std::sin(e), 1e-14);
    EXPECT_NEAR(s.torque_along(-3.0 * Vec3::UnitZ()), 4.0 * 0.1 * std::sin(e), 1e-14);
    // The ball binds when it is smaller.
    EXPECT_DOUBLE_EQ(wheel_torque_slabs(array, 0.01).torque_along(Vec3::UnitZ()), 0.01);
  }
}

TEST(TorqueSlabs, AtGaugeOneTheAllocationReachesAWheelLimitOrTheBall) {
  std::mt19937 rng(7);
  for (const dynamics::ReactionWheelArray& array : arrays()) {
    // τ_max large (the wheels bind) and small (the ball binds in some directions).
    for (const double tau_max : {10.0, 0.6 * array.wheel(0).torque_max}) {
      const TorqueSlabs s = wheel_torque_slabs(array, tau_max);
      for (int trial = 0; trial < 500; ++trial) {
        const Vec3 d = random_unit(rng);
        const Vec3 tau = d / s.gauge(d);
        const dynamics::WheelVector u = array.allocate(tau);
        double worst = tau.norm() / tau_max;
        for (int i = 0; i < array.count(); ++i) {
          const double exact = array.allocation_row(i).dot(tau);
          EXPECT_NEAR(u[static_cast<std::size_t>(i)], exact, 1e-15) << "clipped inside the set";
          worst = std::max(worst, std::abs(exact) / array.wheel(i).torque_max);
        }
        EXPECT_NEAR(worst, 1.0, 1e-12);
      }
    }
  }
}

TEST(TorqueSlabs, TheInflatedGaugeIsTheWorstOverTheErrorBallAndIsAttained) {
  std::mt19937 rng(11);
  for (const dynamics::ReactionWheelArray& array : arrays()) {
    const TorqueSlabs s = wheel_torque_slabs(array, 10.0);
    for (int trial = 0; trial < 200; ++trial) {
      const Vec3 tau = random_unit(rng) * (0.5 / s.gauge(random_unit(rng)));
      const double e = 0.3 * array.wheel(0).torque_max;
      const double bound = s.inflated_gauge(tau, e);
      // No error within the ball exceeds it (sampled) …
      for (int k = 0; k < 200; ++k) {
        EXPECT_LE(s.gauge(tau + e * random_unit(rng)), bound * (1.0 + 1e-12));
      }
      // … and the error along the binding slab's row attains it.
      double attained = s.gauge(tau + e * tau.normalized());
      for (int i = 0; i < s.count; ++i) {
        const Vec3 r = s.rows[static_cast<std::size_t>(i)];
        const double sign = r.dot(tau) >= 0.0 ? 1.0 : -1.0;
        attained = std::max(attained, s.gauge(tau + e * sign * r.normalized()));
      }
      EXPECT_NEAR(attained, bound, 1e-12 * bound);
    }
  }
}

/// A CubeSat slew of 120 deg past a keep-out cone.
plan::PlannedSlew cubesat_plan(plan::SlewProblem& p) {
  Mat3 J;
  J << 0.042, 0.001, 0.0, 0.001, 0.040, 0.0005, 0.0, 0.0005, 0.0075;
  p.J_b = J;
  p.tau_max = 1e-3;
  p.torque_headroom = 0.1;
  p.R_target = lie::exp(Vec3(0.3, 0.2, 1.0).normalized() * 120.0 * kDeg);
  p.cones.push_back(keep_out_cone(Vec3::UnitX(), Vec3(0.2, 0.9, 0.1).normalized(), 20.0 * kDeg));
  return plan::plan_slew(p);
}

TEST(TorqueSlabs, ThePlansGaugeIsTheLargestAlongThePlan) {
  plan::SlewProblem p;
  const plan::PlannedSlew planned = cubesat_plan(p);
  const auto wheels = dynamics::pyramid_wheels(0.6, 6e-4, 0.01);
  const TorqueSlabs s = wheel_torque_slabs(dynamics::ReactionWheelArray(wheels), 2e-3);
  for (const double rate : {0.3, 1.0}) {
    for (const double e : {0.0, 1e-4}) {
      const double bound = s.plan_gauge(planned.plan, rate * rate, e);
      double sampled = 0.0;
      const double T = planned.plan.duration();
      for (int i = 0; i <= 20000; ++i) {
        sampled = std::max(sampled, s.inflated_gauge(rate * rate * planned.plan.evaluate(T * i / 20000.0).tau_b, e));
      }
      EXPECT_LE(sampled, bound * (1.0 + 1e-12));
      EXPECT_GE(sampled, bound * (1.0 - 1e-3)) << "the largest is at a node or a midpoint, which the samples approach";
    }
  }
}

TEST(TorqueSlabs, ThePlannedGovernorSaturatesOntoTheSlabs) {
  plan::SlewProblem p;
  const plan::PlannedSlew planned = cubesat_plan(p);
  const auto wheels = dynamics::pyramid_wheels(0.6, 6e-4, 0.01);
  const dynamics::ReactionWheelArray array(wheels);
  PlannedGovernorParams params{{2e-3, 4e-3}, p.tau_max, 0.1, 0.05, 0.1, 0, std::nullopt};
  params.slabs = wheel_torque_slabs(array, p.tau_max);
  PlannedGovernor gov(planned.plan, p.cones, params);
  std::mt19937 rng(3);
  int saturated = 0;
  for (int trial = 0; trial < 200; ++trial) {
    // Far from the plan's start and spinning: the law asks for more than the wheels give.
    const Mat3 R = lie::exp(random_unit(rng) * 0.5);
    const Vec3 omega = random_unit(rng) * 0.3;
    gov.reset(0.0);
    const PlannedOutput& o = gov.step(0.0, R, omega, Vec3::Zero());
    EXPECT_LE(params.slabs.gauge(o.tau_b), 1.0);
    const dynamics::WheelVector u = array.allocate(o.tau_b);
    for (int i = 0; i < array.count(); ++i) {
      EXPECT_NEAR(u[static_cast<std::size_t>(i)], array.allocation_row(i).dot(o.tau_b), 1e-18);
    }
    if (o.demand_ratio > 1.0) {
      ++saturated;
      EXPECT_NEAR(params.slabs.gauge(o.tau_b), 1.0, 1e-12);
    }
  }
  EXPECT_GT(saturated, 100);
}

}  // namespace
}  // namespace attiguard::governor::torque_slabs_test
