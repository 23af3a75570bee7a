// The slew planner (docs/slew-planner.md): the closed form, constrained problems, refusals.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "attiguard/core/errors.hpp"
#include "attiguard/lie/quaternion.hpp"
#include "attiguard/plan/slew_planner.hpp"

namespace attiguard::plan::slew_planner_test {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

SlewProblem symmetric_problem(double angle_deg, double J, double tau) {
  SlewProblem p;
  p.J_b = J * lie::Mat3::Identity();
  p.tau_max = tau;
  p.torque_headroom = 0.0;
  p.R_target = lie::exp(lie::Vec3(1.0, 2.0, -0.5).normalized() * angle_deg * kDeg);
  return p;
}

class ClosedForm : public ::testing::TestWithParam<double> {};

// An inertially symmetric body, no cones, ‖τ‖ ≤ τ_max: the eigenaxis bang-bang 2√(θJ/τ_max).
TEST_P(ClosedForm, SymmetricBodyPlansTheEigenaxisBangBang) {
  const double angle = GetParam();
  for (const auto& [J, tau] : {std::pair{0.02, 1e-3}, std::pair{1.0, 1.0}, std::pair{4e6, 20.0}}) {
    const SlewProblem p = symmetric_problem(angle, J, tau);
    const PlannedSlew plan = plan_slew(p);
    const double exact = 2.0 * std::sqrt(angle * kDeg * J / tau);
    EXPECT_NEAR(plan.report.duration / exact, 1.0, 0.005) << "angle " << angle << " J " << J;
    EXPECT_LE(plan.report.check.largest_torque_ratio, 1.0);
    EXPECT_LT(plan.report.check.largest_attitude_deviation, 1e-3);
    // The plan ends at rest at the target.
    const governor::SlewPlanSample end = plan.plan.evaluate(plan.plan.duration());
    EXPECT_LT(lie::distance(end.R_ib, p.R_target), 1e-6);
    EXPECT_LT(end.omega_b.norm() * plan.report.duration, 1e-9);
  }
}

INSTANTIATE_TEST_SUITE_P(Angles, ClosedForm, ::testing::Values(10.0, 90.0, 170.0, 179.0));

// A keep-out cone centred on the eigenaxis path (the Sun exactly between start and target).
TEST(SlewPlanner, GoesAroundAConeCentredOnTheEigenaxisPath) {
  SlewProblem p;
  p.J_b = lie::Vec3(1.0, 2.0, 3.0).asDiagonal();
  p.tau_max = 1.0;
  p.R_target = lie::exp(lie::Vec3(0.0, 1.0, 0.0) * 120.0 * kDeg);
  // Body +z sweeps the x–z plane; the Sun at 60 deg along the way.
  const lie::Vec3 sun = lie::exp(lie::Vec3(0.0, 1.0, 0.0) * 60.0 * kDeg) * lie::Vec3::UnitZ();
  p.cones.push_back(governor::keep_out_cone(lie::Vec3::UnitZ(), sun, 30.0 * kDeg));
  p.cone_margin = 1.0 * kDeg;
  const PlannedSlew plan = plan_slew(p);
  EXPECT_GE(plan.report.check.smallest_cone_margin, p.cone_margin);
  EXPECT_LE(plan.report.check.largest_torque_ratio, 1.0 - p.torque_headroom);
  EXPECT_GT(plan.report.ratio, 1.0);
  EXPECT_LT(plan.report.ratio, 3.0);
}

TEST(SlewPlanner, RefusesATargetInsideAKeepOutCone) {
  SlewProblem p = symmetric_problem(90.0, 1.0, 1.0);
  p.cones.push_back(governor::keep_out_cone(lie::Vec3::UnitZ(), p.R_target * lie::Vec3::UnitZ(),
                                            20.0 * kDeg));
  try {
    (void)plan_slew(p);
    FAIL() << "no refusal";
  } catch (const VerificationFailure& e) {
    EXPECT_NE(std::string(e.what()).find("target attitude does not keep cones[0]"), std::string::npos)
        << e.what();
  }
}

// A ring of keep-out cones around the start's body +z: start and target keep every cone, but
// body +z cannot leave the ring's inside whatever the rotation about it, so every way is closed.
// The planner must say so (exit 4), not return a plan or fail in the solver. Over crafts of very
// different sizes (the roadmap's search is geometric, the answer must not depend on J).
TEST(SlewPlanner, RefusesWhenTheConesCloseEveryWay) {
  for (const double J : {0.02, 1.0, 4e6}) {
    SlewProblem p = symmetric_problem(120.0, J, J * 0.05);
    p.R_target = lie::exp(lie::Vec3(0.0, 1.0, 0.0) * 120.0 * kDeg);
    for (int k = 0; k < 12; ++k) {
      const double azimuth = 30.0 * kDeg * k;
      const lie::Vec3 s(std::sin(30.0 * kDeg) * std::cos(azimuth),
                        std::sin(30.0 * kDeg) * std::sin(azimuth), std::cos(30.0 * kDeg));
      p.cones.push_back(governor::keep_out_cone(lie::Vec3::UnitZ(), s, 12.0 * kDeg));
    }
    try {
      (void)plan_slew(p);
      FAIL() << "J " << J << ": a plan through a closed ring of cones";
    } catch (const VerificationFailure& e) {
      EXPECT_NE(std::string(e.what()).find("no admissible path: the cones close every way"),
                std::string::npos)
          << e.what();
    }
  }
}

// A cone far (38 deg) from the eigenaxis path, which the planner therefore leaves out of the
// program, but on the time-optimal path of this asymmetric body (found by planning without it):
// the dense check must catch the plan near it, impose it again and return a plan that keeps it.
TEST(SlewPlanner, AConeLeftOutFarFromTheGuessIsImposedWhenThePlanComesNear) {
  SlewProblem p;
  p.J_b = lie::Vec3(1.0, 2.0, 3.0).asDiagonal();
  p.tau_max = 1.0;
  p.torque_headroom = 0.0;
  p.R_target = lie::exp(lie::Vec3(1.0, 0.0, 1.0).normalized() * 170.0 * kDeg);
  const PlannedSlew free = plan_slew(p);
  // Body +z on the free plan, at its largest angle from the eigenaxis path of body +z.
  lie::Vec3 far_i = lie::Vec3::UnitZ();
  double far_angle = 0.0;
  for (int i = 0; i <= 400; ++i) {
    const lie::Vec3 z_i = free.plan.evaluate(free.plan.duration() * i / 400.0).R_ib * lie::Vec3::UnitZ();
    double nearest = std::numbers::pi;
    for (int j = 0; j <= 400; ++j) {
      const lie::Vec3 e_i = lie::exp(lie::Vec3(1.0, 0.0, 1.0).normalized() * 170.0 * kDeg * j / 400.0) *
                            lie::Vec3::UnitZ();
      nearest = std::min(nearest, std::acos(std::clamp(z_i.dot(e_i), -1.0, 1.0)));
    }
    if (nearest > far_angle) {
      far_angle = nearest;
      far_i = z_i;
    }
  }
  ASSERT_GT(far_angle, 36.0 * kDeg);  // the cone below is left out of the first solve
  p.cones.push_back(governor::keep_out_cone(lie::Vec3::UnitZ(), far_i, 5.0 * kDeg));
  const PlannedSlew plan = plan_slew(p);
  EXPECT_GE(plan.report.cones_reimposed, 1);
  EXPECT_GE(plan.report.check.smallest_cone_margin, 0.0);
  EXPECT_LE(plan.report.check.largest_torque_ratio, 1.0);
  EXPECT_GT(plan.report.duration, free.report.duration);  // the cone costs time
}

}  // namespace
}  // namespace attiguard::plan::slew_planner_test
