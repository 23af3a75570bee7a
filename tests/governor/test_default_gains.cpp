// The PET-ERG's values derived from the craft (governor/default_gains.hpp, docs/pet-erg.md
// section 8): the same dimensionless closed loop from a 10^-2 kg m^2 CubeSat to a 10^7 kg m^2
// station, the flight loop's caps, the room left for the initial rate, the given values kept.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "attiguard/core/errors.hpp"
#include "attiguard/governor/default_gains.hpp"
#include "attiguard/governor/torque_threshold.hpp"
#include "attiguard/lie/so3.hpp"
#include "attiguard/lie/symmetric_eigen.hpp"

namespace attiguard::governor::default_gains_test {
namespace {

using lie::Mat3;
using lie::Vec3;

Mat3 inertia(double scale, double ratio) {
  // principal moments J_max, between, J_max/ratio (a physical triple), rotated off the axes
  const double J_max = scale;
  const double J_min = scale / ratio;
  const double J_mid = std::max(J_min, J_max - 0.5 * J_min);
  const Mat3 Q = lie::exp(Vec3(0.3, -0.5, 0.7));
  return Q * Vec3(J_mid, J_max, J_min).asDiagonal() * Q.transpose();
}

/// The dimensionless groups of docs/pet-erg.md, section 8.
struct Groups {
  double stiffness, damping, rate_gain, sample, c_gamma, epsilon;
};

Groups groups(const CraftScales& c, const DerivedGovernorValues& d) {
  const double J_min = lie::lambda_min(c.J);
  const double J_max = lie::lambda_max(c.J);
  const double gamma_d = compute_torque_threshold({d.kp, d.kd, J_min, d.torque_scale}).gamma_d;
  return {d.kp * d.reference_angle / d.torque_scale,
          d.kd / (2.0 * std::sqrt(d.kp * std::sqrt(J_min * J_max))),
          d.kappa * gamma_d / d.rate_scale,
          d.Ts * d.natural_frequency,
          d.c_gamma,
          d.epsilon};
}

TEST(DefaultGains, TheDimensionlessLoopIsTheSameFromCubeSatToStation) {
  CraftScales paper;
  paper.J = inertia(1.0, 3.0);
  paper.tau_max = 1.0;
  paper.slew_angle = 2.0;
  const Groups reference = groups(paper, derive_governor_values(paper, {}));
  const DefaultGainConstants k;
  EXPECT_NEAR(reference.stiffness, k.stiffness, 1e-12);
  EXPECT_NEAR(reference.damping, k.damping_ratio, 1e-12);
  EXPECT_NEAR(reference.rate_gain, k.rate_gain, 1e-9);
  EXPECT_NEAR(reference.sample, k.sample_fraction, 1e-12);
  for (const double J_scale : {1e-2, 1.0, 1e3, 1e6, 1e7}) {
    for (const double tau : {1e-4, 1e-2, 1.0, 1e2}) {
      CraftScales c = paper;
      c.J = inertia(J_scale, 3.0);
      c.tau_max = tau;
      const DerivedGovernorValues d = derive_governor_values(c, {});
      const Groups g = groups(c, d);
      EXPECT_NEAR(g.stiffness, reference.stiffness, 1e-9 * reference.stiffness) << J_scale << " " << tau;
      EXPECT_NEAR(g.damping, reference.damping, 1e-9) << J_scale << " " << tau;
      EXPECT_NEAR(g.rate_gain, reference.rate_gain, 1e-6 * reference.rate_gain) << J_scale << " " << tau;
      EXPECT_NEAR(g.sample, reference.sample, 1e-9) << J_scale << " " << tau;
      EXPECT_NEAR(g.epsilon, reference.epsilon, 1e-6 * reference.epsilon) << J_scale << " " << tau;
      // the time scale is the craft's own: √(J_max θ/τ)
      EXPECT_NEAR(d.time_scale, std::sqrt(J_scale * 2.0 / tau), 1e-9 * d.time_scale);
      EXPECT_TRUE(d.any_derived());
      EXPECT_FALSE(d.limited_by_control_period);
    }
  }
}

TEST(DefaultGains, GivenValuesAreKeptAndTheRestFollowsThem) {
  CraftScales c;
  c.J = inertia(50.0, 2.0);
  c.tau_max = 0.3;
  c.slew_angle = 1.0;
  GivenGovernorValues given;
  given.kp = 0.7;
  given.kd = 9.0;
  given.kappa = 3.0;
  given.Ts = 0.25;
  given.c_gamma = 3.0;
  given.epsilon = 1e-3;
  const DerivedGovernorValues d = derive_governor_values(c, given);
  EXPECT_EQ(d.kp, 0.7);
  EXPECT_EQ(d.kd, 9.0);
  EXPECT_EQ(d.kappa, 3.0);
  EXPECT_EQ(d.Ts, 0.25);
  EXPECT_EQ(d.c_gamma, 3.0);
  EXPECT_EQ(d.epsilon, 1e-3);
  EXPECT_FALSE(d.any_derived());
  // only k_p given: k_d from it
  GivenGovernorValues only_kp;
  only_kp.kp = 0.7;
  const DerivedGovernorValues e = derive_governor_values(c, only_kp);
  EXPECT_EQ(e.kp, 0.7);
  EXPECT_TRUE(e.kd_derived);
  EXPECT_NEAR(e.damping_ratio, DefaultGainConstants{}.damping_ratio, 1e-12);
}

TEST(DefaultGains, TheFlightLoopPeriodCapsThePdBandwidth) {
  // a fast craft (0.01 kg m², 0.1 N m, tiny slew) in a 1 Hz loop: the derived k_p would put the
  // PD poles beyond the loop's rate; it is lowered to the caps
  CraftScales c;
  c.J = inertia(0.01, 10.0);
  c.tau_max = 0.1;
  c.slew_angle = 0.05;
  c.control_period = 1.0;
  const DerivedGovernorValues d = derive_governor_values(c, {});
  const DefaultGainConstants k;
  EXPECT_TRUE(d.limited_by_control_period);
  EXPECT_LE(d.bandwidth_period, k.bandwidth_period * (1.0 + 1e-12));
  EXPECT_LE(d.damping_period, k.damping_period * (1.0 + 1e-12));
  const double J_min = lie::lambda_min(c.J);
  EXPECT_NEAR(d.bandwidth_period, std::sqrt(d.kp / J_min) * c.control_period, 1e-12);
  // the sampling period is a whole number of control periods, the integration step at most one
  EXPECT_NEAR(std::remainder(d.Ts, c.control_period), 0.0, 1e-12);
  EXPECT_GE(d.Ts, c.control_period);
  EXPECT_LE(d.integrator_step, c.control_period);
}

TEST(DefaultGains, TheInitialRateLeavesRoomBelowGammaD) {
  CraftScales c;
  c.J = inertia(20.0, 2.0);
  c.tau_max = 0.1;
  c.slew_angle = 0.5;
  const Vec3 omega0(0.05, -0.03, 0.04);
  c.initial_kinetic_energy = 0.5 * omega0.dot(c.J * omega0);
  const DerivedGovernorValues at_rest = derive_governor_values(CraftScales{c.J, c.tau_max, 0.0, 0.0, 0.5, 0.0, 0.0}, {});
  const DerivedGovernorValues d = derive_governor_values(c, {});
  EXPECT_LT(c.initial_kinetic_energy, 0.5 * d.gamma_d_estimate * (1.0 + 1e-9));
  EXPECT_GT(at_rest.kp, d.kp);  // a softer loop, larger reference angle
  EXPECT_GT(d.reference_angle, at_rest.reference_angle);
}

TEST(DefaultGains, WheelsAndTheDisturbanceBoundSetTheTorqueScale) {
  CraftScales c;
  c.J = inertia(100.0, 2.0);
  c.tau_max = 1.0;
  c.slew_angle = 1.0;
  c.wheel_torque_radius = 0.4;
  c.disturbance_bound = 0.1;
  EXPECT_NEAR(effective_torque(c), 0.3, 1e-15);
  EXPECT_NEAR(derive_governor_values(c, {}).torque_scale, 0.3, 1e-15);
  c.disturbance_bound = 0.4;
  EXPECT_THROW((void)derive_governor_values(c, {}), SetupError);
}

TEST(DefaultGains, RefusesInputsWithoutAScale) {
  CraftScales c;
  c.J = inertia(1.0, 2.0);
  c.tau_max = 1.0;
  CraftScales bad = c;
  bad.tau_max = std::nan("");
  EXPECT_THROW((void)derive_governor_values(bad, {}), SetupError);
  bad = c;
  bad.J(0, 0) = -5.0;
  EXPECT_THROW((void)derive_governor_values(bad, {}), SetupError);
  bad = c;
  bad.slew_angle = std::numeric_limits<double>::infinity();
  EXPECT_THROW((void)derive_governor_values(bad, {}), SetupError);
  bad = c;
  bad.control_period = -1.0;
  EXPECT_THROW((void)derive_governor_values(bad, {}), SetupError);
  // a hold (no slew) still has a scale: the floor of θ_ref
  const DerivedGovernorValues hold = derive_governor_values(c, {});
  EXPECT_NEAR(hold.reference_angle, DefaultGainConstants{}.min_angle, 1e-15);
}

}  // namespace
}  // namespace attiguard::governor::default_gains_test
