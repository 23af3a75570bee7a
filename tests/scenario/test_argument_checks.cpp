// Tests of scenario/argument_checks.hpp: the rotation-form checks of library arguments
// (docs/python.md, "Validation").

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "attiguard/core/errors.hpp"
#include "attiguard/scenario/argument_checks.hpp"

namespace attiguard::scenario {
namespace {

std::string message_of(const auto& call) {
  try {
    call();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ArgumentChecks, UnitQuaternionRefusesNonUnitAndNaNNamingTheArgument) {
  EXPECT_NO_THROW((void)checked_unit_quaternion(lie::Quat(1, 0, 0, 0), "q", "f()"));
  const std::string zero = message_of([] { (void)checked_unit_quaternion(lie::Quat(0, 0, 0, 0), "q", "f()"); });
  EXPECT_NE(zero.find("f(): q: not a unit quaternion"), std::string::npos) << zero;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::string bad = message_of([&] { (void)checked_unit_quaternion(lie::Quat(nan, 0, 0, 0), "q", "f()"); });
  EXPECT_NE(bad.find("f(): q[0]:"), std::string::npos) << bad;
}

TEST(ArgumentChecks, AxisAngleRefusesAZeroAxisAndReturnsTheUnitAxis) {
  const std::string zero = message_of([] { (void)checked_axis_angle(lie::Vec3::Zero(), 1.0, "axis", "angle", "f()"); });
  EXPECT_NE(zero.find("f(): axis:"), std::string::npos) << zero;
  const lie::Vec3 k = checked_axis_angle(lie::Vec3(1e-200, 0, 0), 1.0, "axis", "angle", "f()");
  EXPECT_DOUBLE_EQ(k.norm(), 1.0);
  const std::string far = message_of([] { (void)checked_axis_angle(lie::Vec3(1, 0, 0), 1e300, "axis", "angle", "f()"); });
  EXPECT_NE(far.find("f(): angle:"), std::string::npos) << far;
}

TEST(ArgumentChecks, RotationVectorAndMatrixRefuseNonFinite) {
  const double inf = std::numeric_limits<double>::infinity();
  const std::string w = message_of([&] { (void)checked_rotation_vector(lie::Vec3(inf, 0, 0), "w", "f()"); });
  EXPECT_NE(w.find("f(): w[0]:"), std::string::npos) << w;
  lie::Mat3 M = lie::Mat3::Identity();
  M(1, 2) = inf;
  EXPECT_THROW((void)checked_matrix3(M, "M", "f()"), InputError);
}

}  // namespace
}  // namespace attiguard::scenario
