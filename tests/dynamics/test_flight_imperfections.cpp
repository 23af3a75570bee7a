// The imperfection models of the flight loop (docs/pet-erg.md, section 11): bounded random
// vectors, the disturbance torque, the attitude/rate sensors and the torque quantiser.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "attiguard/control/torque_quantizer.hpp"
#include "attiguard/dynamics/attitude_sensor.hpp"
#include "attiguard/dynamics/bounded_noise.hpp"
#include "attiguard/dynamics/disturbance_torque.hpp"

namespace attiguard::dynamics {
namespace {

using lie::Mat3;
using lie::Vec3;

TEST(BoundedNoise, UniformInTheBallDeterministicAndBounded) {
  int inner = 0;
  Vec3 mean = Vec3::Zero();
  const int n = 20000;
  for (int k = 0; k < n; ++k) {
    const Vec3 v = uniform_in_ball(42, 7, static_cast<std::uint64_t>(k), 2.0);
    ASSERT_LE(v.norm(), 2.0);
    EXPECT_EQ(v, uniform_in_ball(42, 7, static_cast<std::uint64_t>(k), 2.0));
    inner += v.norm() <= 1.0 ? 1 : 0;
    mean += v / n;
  }
  // Uniform in the volume: P(‖v‖ ≤ r/2) = 1/8 (σ of the estimate ≈ 0.0023).
  EXPECT_NEAR(static_cast<double>(inner) / n, 0.125, 0.01);
  EXPECT_LT(mean.norm(), 0.05);
  EXPECT_NE(uniform_in_ball(42, 7, 0, 1.0), uniform_in_ball(43, 7, 0, 1.0));
  EXPECT_NE(uniform_in_ball(42, 7, 0, 1.0), uniform_in_ball(42, 8, 0, 1.0));
  EXPECT_EQ(uniform_in_ball(42, 7, 0, 0.0), Vec3::Zero());
}

TEST(DisturbanceTorque, EveryKindStaysWithinItsBound) {
  for (const DisturbanceKind kind : {DisturbanceKind::none, DisturbanceKind::constant,
                                     DisturbanceKind::sinusoidal, DisturbanceKind::random}) {
    DisturbanceTorque d;
    d.kind = kind;
    d.bound = 0.03;
    d.axis_b = Vec3(1.0, 2.0, -2.0).normalized();
    d.period = 7.0;
    d.hold = 0.1;
    d.seed = 3;
    double largest = 0.0;
    for (int i = 0; i < 5000; ++i) {
      const double t = 0.0137 * i;
      largest = std::max(largest, d.at(t).norm());
      EXPECT_LE(d.at(t).norm(), d.bound * (1.0 + 1e-15)) << static_cast<int>(kind) << " t " << t;
    }
    if (kind == DisturbanceKind::none) {
      EXPECT_EQ(largest, 0.0);
    } else {
      EXPECT_GT(largest, 0.8 * d.bound) << static_cast<int>(kind);  // the bound is used
    }
  }
}

TEST(DisturbanceTorque, ShapesConstantSinusoidalAndHeldRandom) {
  DisturbanceTorque d;
  d.bound = 0.5;
  d.axis_b = Vec3::UnitY();
  d.kind = DisturbanceKind::constant;
  EXPECT_EQ(d.at(12.3), Vec3(0.0, 0.5, 0.0));
  d.kind = DisturbanceKind::sinusoidal;
  d.period = 8.0;
  EXPECT_NEAR(d.at(2.0)(1), 0.5, 1e-15);
  EXPECT_NEAR(d.at(6.0)(1), -0.5, 1e-15);
  d.kind = DisturbanceKind::random;
  d.hold = 0.1;
  EXPECT_EQ(d.at(0.31), d.at(0.39));  // held over one period
  EXPECT_NE(d.at(0.31), d.at(0.41));  // a new value in the next
}

TEST(AttitudeSensor, ErrorsStayWithinBiasPlusNoise) {
  AttitudeSensor s;
  s.attitude_bias_b = Vec3(0.001, -0.002, 0.0005);
  s.attitude_noise = 0.003;
  s.rate_bias_b = Vec3(0.0, 0.001, 0.0);
  s.rate_noise = 0.002;
  s.seed = 9;
  const Mat3 R = lie::exp(Vec3(0.3, -1.0, 2.0));
  const Vec3 omega(0.1, -0.2, 0.05);
  double worst_R = 0.0;
  for (std::uint64_t k = 0; k < 5000; ++k) {
    const Measurement m = s.measure(R, omega, k);
    worst_R = std::max(worst_R, lie::distance(m.R_ib, R));
    EXPECT_LE(lie::distance(m.R_ib, R), s.attitude_error_bound() + 1e-12);
    EXPECT_LE((m.omega_b - omega).norm(), s.rate_error_bound() + 1e-15);
  }
  EXPECT_GT(worst_R, s.attitude_bias_b.norm());  // the noise adds to the bias
  AttitudeSensor bias_only;
  bias_only.attitude_bias_b = s.attitude_bias_b;
  bias_only.rate_bias_b = s.rate_bias_b;
  const Measurement m = bias_only.measure(R, omega, 17);
  EXPECT_LT(lie::distance(m.R_ib, R * lie::exp(s.attitude_bias_b)), 1e-15);
  EXPECT_EQ(m.omega_b, omega + s.rate_bias_b);
}

TEST(TorqueQuantizer, RoundsEachComponentToTheQuantum) {
  const Vec3 tau(0.123, -0.0449, 0.0051);
  const Vec3 q = control::quantize_torque(tau, 0.01);
  EXPECT_NEAR(q(0), 0.12, 1e-15);
  EXPECT_NEAR(q(1), -0.04, 1e-15);
  EXPECT_NEAR(q(2), 0.01, 1e-15);
  EXPECT_LE((q - tau).norm(), std::sqrt(3.0) / 2.0 * 0.01);
  EXPECT_EQ(control::quantize_torque(tau, 0.0), tau);
}

}  // namespace
}  // namespace attiguard::dynamics
