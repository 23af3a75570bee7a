// The governor's design (governor/governor_design.hpp, docs/pet-erg.md sections 12-13) from
// plain values: the wheel polytope, the bounded step, the robust margin with its reduced torque
// limits and tightened cones, and the refusals with the messages of docs/errors.md.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "attiguard/core/errors.hpp"
#include "attiguard/dynamics/reaction_wheel_array.hpp"
#include "attiguard/governor/attitude_governor.hpp"
#include "attiguard/governor/governor_design.hpp"
#include "attiguard/governor/polytope_torque_threshold.hpp"
#include "attiguard/governor/robust_margin.hpp"

namespace attiguard::governor {
namespace {

using lie::Mat3;
using lie::Vec3;

constexpr double kDeg = std::numbers::pi / 180.0;

/// The values of examples/pet_erg_robust_campaign.toml (without its dispersions), written out.
GovernorDesignInputs robust_campaign() {
  GovernorDesignInputs in;
  in.params.mode = GovernorMode::pet;
  in.params.gains = {0.5, 6.0};
  in.params.J << 120.0, 5.0, -3.0, 5.0, 90.0, 2.0, -3.0, 2.0, 150.0;
  in.params.tau_max = 1.0;
  in.params.kappa = 20.0;
  in.params.Ts = 1.0;
  in.cones = {keep_out_cone(Vec3::UnitX(), Vec3(0.49, 0.85, 0.17), 40.0 * kDeg, 0.002, 0.05, 0.1),
              keep_out_cone(Vec3::UnitX(), Vec3(-0.81, 0.47, -0.34), 15.0 * kDeg, 0.002, 0.05, 0.1),
              keep_in_cone(Vec3::UnitZ(), Vec3::UnitZ(), 60.0 * kDeg)};
  for (const Vec3& axis : {Vec3(0.577382, 0.577382, 0.577288), Vec3(-0.577382, 0.577382, 0.577288),
                           Vec3(-0.577382, -0.577382, 0.577288), Vec3(0.577382, -0.577382, 0.577288)}) {
    in.wheels.push_back({axis.normalized(), 0.1, 6.0, 0.0});
  }
  in.control_period = 0.1;
  in.margins = Margins::robust;
  in.bounds.disturbance = 0.003;
  in.bounds.attitude_bias = 0.0215;
  in.bounds.attitude_noise = 0.0002;
  in.bounds.rate_bias = std::hypot(0.00001, 0.00001);
  in.bounds.rate_noise = 0.00002;
  in.bounds.delay_periods = 1;
  in.bounds.torque_quantum = 0.001;
  in.max_reference_step = 0.002;
  return in;
}

std::string design_error(const GovernorDesignInputs& in) {
  try {
    (void)design(in);
  } catch (const SetupError& e) {
    return e.what();
  }
  return "";
}

TEST(GovernorDesign, NominalWithoutWheelsIsTheUsersParametersWithTheBoundedStepInTheFlightLoop) {
  GovernorDesignInputs in = robust_campaign();
  in.wheels.clear();
  in.margins = Margins::nominal;
  in.params.polytope_gamma_d = 0.3;  // outputs of the design: ignored on input
  in.params.bounded_step = false;
  in.params.robust = RobustMargin{};
  const GovernorDesign d = design(in);
  EXPECT_TRUE(d.params.bounded_step);
  EXPECT_EQ(d.params.polytope_gamma_d, 0.0);
  EXPECT_FALSE(d.params.robust.has_value());
  EXPECT_EQ(d.params.tau_max, in.params.tau_max);
  EXPECT_EQ(d.params.gains.kp, in.params.gains.kp);
  EXPECT_EQ(d.params.J, in.params.J);
  EXPECT_EQ(d.wheels.binding, -1);
  EXPECT_EQ(d.tau_max_reduced, 0.0);
  ASSERT_EQ(d.cones.size(), in.cones.size());
  for (std::size_t i = 0; i < d.cones.size(); ++i) EXPECT_EQ(d.cones[i].delta, in.cones[i].delta) << i;
  in.control_period = 0.0;  // the continuous-time loop of the paper
  EXPECT_FALSE(design(in).params.bounded_step);
}

TEST(GovernorDesign, WheelsGiveTheirPolytopesThreshold) {
  GovernorDesignInputs in = robust_campaign();
  in.margins = Margins::nominal;
  const GovernorDesign d = design(in);
  const dynamics::ReactionWheelArray array(in.wheels);
  std::vector<Vec3> rows;
  std::vector<double> limits;
  for (int i = 0; i < array.count(); ++i) {
    rows.push_back(array.allocation_row(i));
    limits.push_back(array.wheel(i).torque_max);
  }
  int binding = -1;
  const TorqueThreshold t =
      compute_polytope_torque_threshold(in.params.gains.kp, in.params.gains.kd, in.params.J, rows, limits, &binding);
  EXPECT_EQ(d.wheels.gamma_d, t.gamma_d);
  EXPECT_EQ(d.wheels.gamma_d_upper, t.upper_bound);
  EXPECT_EQ(d.wheels.binding, binding);
  EXPECT_EQ(d.params.polytope_gamma_d, t.gamma_d);
  EXPECT_EQ(wheel_polytope(in).gamma_d, t.gamma_d);
  // the governor built from it takes the smaller of the ball's and the polytope's Γ_d
  const AttitudeGovernor gov(d.params, d.cones);
  EXPECT_EQ(gov.gamma_d(), std::min(gov.torque_threshold().gamma_d, t.gamma_d));
}

TEST(GovernorDesign, RobustMarginsReduceTheLimitsByTheCommandErrorAndTightenTheCones) {
  const GovernorDesignInputs in = robust_campaign();
  const GovernorDesign d = design(in);
  ASSERT_TRUE(d.params.robust.has_value());
  const RobustMargin& m = *d.params.robust;
  EXPECT_GT(m.command_error, 0.0);
  EXPECT_EQ(d.tau_max_reduced, in.params.tau_max - m.command_error);
  EXPECT_EQ(d.params.tau_max, d.tau_max_reduced);
  EXPECT_EQ(d.params.polytope_gamma_d, d.wheel_gamma_d_reduced);
  EXPECT_LT(d.wheel_gamma_d_reduced, d.wheels.gamma_d);
  EXPECT_GT(m.gamma_min, 0.0);
  EXPECT_LT(m.gamma_min, (1.0 - m.delta) * d.wheel_gamma_d_reduced);
  EXPECT_EQ(m.max_reference_step, 0.002);
  ASSERT_EQ(d.cones.size(), in.cones.size());
  for (std::size_t i = 0; i < in.cones.size(); ++i) {
    EXPECT_NEAR(d.cones[i].theta_c, in.cones[i].theta_c - in.bounds.attitude_bias, 1e-15) << i;
    EXPECT_GE(d.cones[i].delta - d.cones[i].cos_theta_c, in.cones[i].delta - in.cones[i].cos_theta_c - 1e-15) << i;
    EXPECT_NEAR(d.cones[i].zeta - d.cones[i].delta, in.cones[i].zeta - in.cones[i].delta, 1e-12) << i;
  }
  // the nominal polytope is reported as without robust margins
  GovernorDesignInputs nominal = in;
  nominal.margins = Margins::nominal;
  EXPECT_EQ(design(nominal).wheels.gamma_d, d.wheels.gamma_d);
  const AttitudeGovernor gov(d.params, d.cones);
  EXPECT_GT(gov.gamma(Mat3::Identity()), m.gamma_min);
}

TEST(GovernorDesign, RefusesWhatTheFlightLoopOrTheBoundsDoNotAllow) {
  GovernorDesignInputs in = robust_campaign();
  in.control_period = 0.0;
  EXPECT_EQ(design_error(in), "reaction wheels act in the flight loop: set [control] control_period > 0");
  in.wheels.clear();
  EXPECT_EQ(design_error(in), "robust margins are for the flight loop: set control_period > 0");
  in = robust_campaign();
  in.params.mode = GovernorMode::none;
  EXPECT_EQ(design_error(in), "robust margins are margins of the governor: governor = \"none\" has none");
  in = robust_campaign();
  in.bounds.disturbance = 0.03;
  EXPECT_EQ(design_error(in).rfind("no admissible set with robust margins: Gamma_min = ", 0), 0U) << design_error(in);
  in = robust_campaign();
  in.bounds.rate_noise = 0.05;
  EXPECT_EQ(design_error(in).rfind("no admissible set with robust margins: the command error bound", 0), 0U)
      << design_error(in);
  in = robust_campaign();
  in.wheels.resize(2);  // two axes do not span R³
  EXPECT_NE(design_error(in), "");
  in.margins = Margins::nominal;
  EXPECT_NE(design_error(in), "");
}

}  // namespace
}  // namespace attiguard::governor
