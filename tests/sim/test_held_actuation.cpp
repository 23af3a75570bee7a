// The held actuation of the pet_erg flight loop (sim/held_actuation.hpp; docs/pet-erg.md,
// sections 10-12): the command held until the next one, one period of delay, quantisation,
// allocation to reaction wheels with their clip and demand ratio, the wheels' momenta linear
// between commands, and the sensors' sample k fed to the governor at each control instant.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <type_traits>
#include <utility>
#include <vector>

#include "attiguard/control/torque_quantizer.hpp"
#include "attiguard/core/errors.hpp"
#include "attiguard/dynamics/reaction_wheel_array.hpp"
#include "attiguard/governor/attitude_governor.hpp"
#include "attiguard/lie/so3.hpp"
#include "attiguard/sim/held_actuation.hpp"

namespace attiguard::sim {
namespace {

using dynamics::ReactionWheel;
using dynamics::WheelVector;
using lie::Mat3;
using lie::Vec3;

static_assert(noexcept(std::declval<HeldActuation&>().command(0.0, std::declval<const Vec3&>())));
static_assert(noexcept(std::declval<HeldActuation&>().control(
    std::declval<governor::AttitudeGovernor&>(), 0.0, std::declval<const Mat3&>(),
    std::declval<const Vec3&>(), std::declval<const Mat3&>())));
static_assert(noexcept(std::declval<const HeldActuation&>().momenta(0.0)));
static_assert(noexcept(std::declval<HeldActuation&>().observe_momenta(0.0)));

/// Imperfections with only a delay and a quantum.
PetErgImperfections held_imperfections(int delay_periods, double torque_quantum) {
  PetErgImperfections im;
  im.delay_periods = delay_periods;
  im.torque_quantum = torque_quantum;
  return im;
}

/// The 4-wheel pyramid of docs/pet-erg.md, section 12 (u_max = 1.5 N·m, h_max = 2 N·m·s), each
/// wheel starting with momentum h0.
std::vector<ReactionWheel> held_pyramid(double h0) {
  const double elevation = std::atan(1.0 / std::numbers::sqrt2);
  const std::array<ReactionWheel, 4> p = dynamics::pyramid_wheels(elevation, 1.5, 2.0);
  std::vector<ReactionWheel> wheels(p.begin(), p.end());
  for (ReactionWheel& w : wheels) w.momentum0 = h0;
  return wheels;
}

/// A⁺ = Aᵀ(AAᵀ)⁻¹ of the wheels' axes, computed here (rows r_i).
Eigen::Matrix<double, Eigen::Dynamic, 3> held_pseudo_inverse(const std::vector<ReactionWheel>& wheels) {
  Eigen::Matrix<double, 3, Eigen::Dynamic> A(3, static_cast<Eigen::Index>(wheels.size()));
  for (std::size_t i = 0; i < wheels.size(); ++i) {
    A.col(static_cast<Eigen::Index>(i)) = wheels[i].axis_b.normalized();
  }
  return A.transpose() * (A * A.transpose()).inverse();
}

TEST(HeldActuation, HoldsTheLastCommandUntilTheNextOne) {
  HeldActuation act(held_imperfections(0, 0.0), {});
  EXPECT_FALSE(act.has_wheels());
  EXPECT_EQ(act.torque_b(), Vec3::Zero());  // nothing applied before the first control instant
  const Vec3 a(0.3, -0.7, 0.11);
  act.command(0.0, a);
  EXPECT_EQ(act.torque_b(), a);
  act.observe_momenta(0.05);
  EXPECT_EQ(act.torque_b(), a);  // held between the instants
  const Vec3 b(-0.2, 0.4, 1.3);
  act.command(0.1, b);
  EXPECT_EQ(act.torque_b(), b);
  EXPECT_EQ(act.max_wheel_torque_ratio(), 0.0);
  EXPECT_EQ(act.max_wheel_momentum_ratio(), 0.0);
}

TEST(HeldActuation, DelayAppliesEachCommandOnePeriodLate) {
  HeldActuation act(held_imperfections(1, 0.0), {});
  const std::array<Vec3, 3> commands{Vec3(0.3, -0.7, 0.11), Vec3(-0.2, 0.4, 1.3), Vec3(1.0, 2.0, 3.0)};
  act.command(0.0, commands[0]);
  EXPECT_EQ(act.torque_b(), Vec3::Zero());  // zero on the first period
  act.command(0.1, commands[1]);
  EXPECT_EQ(act.torque_b(), commands[0]);
  act.command(0.2, commands[2]);
  EXPECT_EQ(act.torque_b(), commands[1]);
}

TEST(HeldActuation, QuantisationRoundsEachComponentToTheNearestMultiple) {
  const double q = 0.01;
  HeldActuation act(held_imperfections(0, q), {});
  const Vec3 tau(0.1234, -0.4561, 0.0151);
  act.command(0.0, tau);
  const Vec3& applied = act.torque_b();
  EXPECT_NEAR(applied(0), 0.12, 1e-15);
  EXPECT_NEAR(applied(1), -0.46, 1e-15);
  EXPECT_NEAR(applied(2), 0.02, 1e-15);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(applied(c) / q, std::round(applied(c) / q), 1e-9) << c;
    EXPECT_LE(std::abs(applied(c) - tau(c)), 0.5 * q + 1e-15) << c;
  }
}

TEST(HeldActuation, WheelsAllocateTheMinimumNormTorquesAndClipThemAtTheirLimits) {
  const std::vector<ReactionWheel> wheels = held_pyramid(0.0);
  const auto pinv = held_pseudo_inverse(wheels);
  HeldActuation act(held_imperfections(0, 0.0), wheels);
  ASSERT_TRUE(act.has_wheels());
  ASSERT_EQ(act.wheels().count(), 4);

  const Vec3 tau(0.3, -0.2, 0.1);
  act.command(0.0, tau);
  EXPECT_LT((act.torque_b() - tau).norm(), 1e-12);  // A A⁺ τ = τ within the limits
  const Eigen::VectorXd u = pinv * tau;
  Vec3 sum = Vec3::Zero();
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(act.wheel_torques()[static_cast<std::size_t>(i)], u(i), 1e-12) << i;
    sum += act.wheel_torques()[static_cast<std::size_t>(i)] * wheels[static_cast<std::size_t>(i)].axis_b.normalized();
  }
  EXPECT_LT((sum - act.torque_b()).norm(), 1e-12);
  EXPECT_NEAR(act.max_wheel_torque_ratio(), u.cwiseAbs().maxCoeff() / 1.5, 1e-12);
  EXPECT_LT(act.max_wheel_torque_ratio(), 1.0);

  // A demand beyond the wheels' limits: clipped, and the ratio says so.
  const Vec3 large(10.0, 0.0, 0.0);
  act.command(0.1, large);
  const Eigen::VectorXd demand = pinv * large;
  EXPECT_NEAR(act.max_wheel_torque_ratio(), demand.cwiseAbs().maxCoeff() / 1.5, 1e-12);
  EXPECT_GT(act.max_wheel_torque_ratio(), 1.0);
  for (int i = 0; i < 4; ++i) {
    EXPECT_LE(std::abs(act.wheel_torques()[static_cast<std::size_t>(i)]), 1.5) << i;
  }
  EXPECT_LT(act.torque_b().norm(), large.norm() - 1.0);
}

TEST(HeldActuation, WheelMomentaAreLinearBetweenCommandsAndRestartAtEach) {
  const double h0 = 0.5;
  const std::vector<ReactionWheel> wheels = held_pyramid(h0);
  HeldActuation act(held_imperfections(0, 0.0), wheels);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(act.momenta(3.0)[static_cast<std::size_t>(i)], h0) << i;

  act.command(0.0, Vec3(0.3, -0.2, 0.1));
  const WheelVector u1 = act.wheel_torques();
  const WheelVector at2 = act.momenta(2.0);
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(at2[static_cast<std::size_t>(i)], h0 - 2.0 * u1[static_cast<std::size_t>(i)], 1e-15) << i;
  }
  act.command(2.0, Vec3(-0.1, 0.4, 0.2));
  const WheelVector u2 = act.wheel_torques();
  const WheelVector at3 = act.momenta(3.0);
  Vec3 momentum_b = Vec3::Zero();
  double ratio = 0.0;
  for (std::size_t i = 0; i < 4; ++i) {
    const double h = h0 - 2.0 * u1[i] - 1.0 * u2[i];  // ḣ = −u, u held on each period
    EXPECT_NEAR(at3[i], h, 1e-14) << i;
    momentum_b += h * wheels[i].axis_b.normalized();
    ratio = std::max(ratio, std::abs(h) / 2.0);
  }
  EXPECT_LT((act.momentum_b(3.0) - momentum_b).norm(), 1e-14);
  act.observe_momenta(3.0);
  EXPECT_NEAR(act.max_wheel_momentum_ratio(), ratio, 1e-15);
  // The momenta at t = 2 (where the second command restarted them) fold into the maximum.
  double ratio2 = 0.0;
  for (std::size_t i = 0; i < 4; ++i) ratio2 = std::max(ratio2, std::abs(at2[i]) / 2.0);
  ASSERT_NE(ratio2, ratio);
  act.observe_momenta(2.0);
  EXPECT_NEAR(act.max_wheel_momentum_ratio(), std::max(ratio, ratio2), 1e-15);
}

TEST(HeldActuation, DelayedWheelTorquesStartAtZeroAndKeepTheMomentaUntilTheSecondCommand) {
  const double h0 = -0.25;
  HeldActuation act(held_imperfections(1, 0.0), held_pyramid(h0));
  const Vec3 tau(0.3, -0.2, 0.1);
  act.command(0.0, tau);
  EXPECT_EQ(act.torque_b(), Vec3::Zero());
  for (int i = 0; i < 4; ++i) EXPECT_EQ(act.momenta(0.1)[static_cast<std::size_t>(i)], h0) << i;
  act.command(0.1, Vec3(1.0, 1.0, 1.0));
  EXPECT_LT((act.torque_b() - tau).norm(), 1e-12);  // the command of t = 0, from t = 0.1
  const WheelVector u = act.wheel_torques();
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(act.momenta(0.3)[static_cast<std::size_t>(i)], h0 - 0.2 * u[static_cast<std::size_t>(i)], 1e-15);
  }
}

TEST(HeldActuation, ControlStepsTheGovernorOnTheSensorsSampleKAndCommandsItsTorque) {
  governor::GovernorParams params;
  params.J = Vec3(1.0, 2.0, 3.0).asDiagonal();
  params.tau_max = 2.5;
  params.bounded_step = true;
  governor::AttitudeGovernor gov(params, {});
  governor::AttitudeGovernor twin(params, {});
  PetErgImperfections im = held_imperfections(0, 0.01);
  im.sensor.attitude_bias_b = Vec3(0.001, -0.002, 0.001);
  im.sensor.attitude_noise = 0.002;
  im.sensor.rate_bias_b = Vec3(0.0005, 0.0, -0.0005);
  im.sensor.rate_noise = 0.003;
  im.sensor.seed = 11;
  HeldActuation act(im, {});
  gov.reset(0.0, Mat3::Identity());
  twin.reset(0.0, Mat3::Identity());
  const Mat3 R_d = lie::exp(Vec3(0.0, 0.5 * std::numbers::pi, 0.0));
  for (int k = 0; k < 6; ++k) {
    const double t = 0.1 * k;
    const Mat3 R_ib = lie::exp(Vec3(0.05 * k, -0.02 * k, 0.01));
    const Vec3 omega_b(0.2 - 0.01 * k, 0.3, 0.4 + 0.02 * k);
    const governor::GovernorOutput& out = act.control(gov, t, R_ib, omega_b, R_d);
    const dynamics::Measurement m = im.sensor.measure(R_ib, omega_b, static_cast<std::uint64_t>(k));
    // The sample index matters: the next sample's noise is another draw.
    ASSERT_NE(im.sensor.measure(R_ib, omega_b, static_cast<std::uint64_t>(k + 1)).omega_b, m.omega_b);
    const governor::GovernorOutput& expected = twin.step(t, m.R_ib, m.omega_b, R_d);
    EXPECT_EQ(out.tau_b, expected.tau_b) << k;
    EXPECT_EQ(gov.reference(), twin.reference()) << k;
    EXPECT_EQ(act.torque_b(), control::quantize_torque(expected.tau_b, 0.01)) << k;
    EXPECT_NE(act.torque_b(), Vec3::Zero()) << k;
  }
}

TEST(HeldActuation, RefusesAWheelSetThatIsNotAnArray) {
  std::vector<ReactionWheel> two = held_pyramid(0.0);
  two.resize(2);
  EXPECT_THROW((void)HeldActuation(held_imperfections(0, 0.0), two), SetupError);
}

}  // namespace
}  // namespace attiguard::sim
