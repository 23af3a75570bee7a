// The waypoint paper's plant (2)-(5): the main engine pushes along its actual body axis
// (x_b by default, a misaligned axis when given), RCT forces add in the body frame.

#include <gtest/gtest.h>

#include <cmath>

#include "attiguard/dynamics/spacecraft_plant.hpp"
#include "attiguard/lie/so3.hpp"

namespace ad = attiguard::dynamics;
using attiguard::lie::Mat3;
using attiguard::lie::Vec3;

TEST(SpacecraftPlant, MainThrustActsAlongTheEngineAxisInTheInertialFrame) {
  const Mat3 J = Vec3(20.0, 20.0, 20.0).asDiagonal();
  const Mat3 R_ib = attiguard::lie::exp(Vec3(0.3, -0.2, 0.5));
  ad::SpacecraftInputs u;
  u.thrust = 20.0;
  u.f_rct_b = Vec3(0.0, 0.5, 0.0);

  const ad::SpacecraftPlant aligned(100.0, J);
  EXPECT_LT((aligned.acceleration_i(R_ib, u) - R_ib * Vec3(20.0, 0.5, 0.0) / 100.0).norm(), 1e-15);

  const double tilt = 0.5 * M_PI / 180.0;  // 0.5 deg misalignment towards body z
  const Vec3 axis_b(std::cos(tilt), 0.0, std::sin(tilt));
  const ad::SpacecraftPlant misaligned(100.0, J, 0.0, axis_b);
  const Vec3 a_i = misaligned.acceleration_i(R_ib, u);
  EXPECT_LT((a_i - R_ib * (20.0 * axis_b + u.f_rct_b) / 100.0).norm(), 1e-15);
  // The lateral error the guidance (which points x_b) does not know about: T sin(tilt)/m.
  EXPECT_NEAR((R_ib.transpose() * a_i).z(), 20.0 * std::sin(tilt) / 100.0, 1e-15);
  // The derivative uses the same acceleration.
  ad::SpacecraftState y;
  y.R[0] = R_ib;
  y.x.setZero();
  EXPECT_LT((misaligned.derivative(y, u).segment<3>(9) - a_i).norm(), 1e-15);
}
