// Reaction-wheel arrays (dynamics/reaction_wheel_array.hpp, docs/pet-erg.md section 12).

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "attiguard/core/errors.hpp"
#include "attiguard/dynamics/reaction_wheel_array.hpp"

namespace attiguard::dynamics {
namespace {

using lie::Vec3;

TEST(ReactionWheelArray, PseudoInverseAllocationReproducesTheTorqueAndClipsAtTheLimits) {
  const auto wheels = pyramid_wheels(35.26 * std::numbers::pi / 180.0, 0.2, 5.0);
  const ReactionWheelArray array(wheels);
  ASSERT_EQ(array.count(), 4);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(array.wheel(i).axis_b.norm(), 1.0, 1e-15);
  const Vec3 tau(0.05, -0.03, 0.08);
  const WheelVector u = array.allocate(tau);
  EXPECT_LT((array.body_torque(u) - tau).norm(), 1e-15);
  // Minimum norm: u ⟂ the null space of A (for the pyramid, (1, −1, 1, −1) up to sign).
  EXPECT_NEAR(u[0] - u[1] + u[2] - u[3], 0.0, 1e-15);
  const WheelVector big = array.allocate(100.0 * tau);
  for (int i = 0; i < 4; ++i) EXPECT_LE(std::abs(big[static_cast<std::size_t>(i)]), 0.2);
}

TEST(ReactionWheelArray, RejectsCoplanarAxesAndBadLimits) {
  const std::vector<ReactionWheel> coplanar{{Vec3::UnitX(), 0.1, 1.0, 0.0},
                                            {Vec3::UnitY(), 0.1, 1.0, 0.0},
                                            {Vec3(1.0, 1.0, 0.0), 0.1, 1.0, 0.0}};
  EXPECT_THROW(ReactionWheelArray{coplanar}, SetupError);
  std::vector<ReactionWheel> ok{{Vec3::UnitX(), 0.1, 1.0, 0.0},
                                {Vec3::UnitY(), 0.1, 1.0, 0.0},
                                {Vec3::UnitZ(), 0.1, 1.0, 0.0}};
  EXPECT_NO_THROW(ReactionWheelArray{ok});
  ok[1].momentum0 = 2.0;  // |h(0)| > h_max
  EXPECT_THROW(ReactionWheelArray{ok}, SetupError);
  ok[1].momentum0 = 0.0;
  ok[2].torque_max = 0.0;
  EXPECT_THROW(ReactionWheelArray{ok}, SetupError);
}

}  // namespace
}  // namespace attiguard::dynamics
