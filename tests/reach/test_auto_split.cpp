// Automatic splitting of the initial set (docs/reach.md, "Automatic splitting"; auto_split.hpp):
// the children cover their parent, the ball with the larger cover radius is split, a cell whose
// own nominal violates the specification is not split, and the budget ends the splitting with
// its reason.

#include <gtest/gtest.h>

#include <random>

#include "attiguard/lie/so3.hpp"
#include "attiguard/lie/quaternion.hpp"
#include "attiguard/reach/auto_split.hpp"
#include "attiguard/reach/simulate.hpp"
#include "reach/pd_example.hpp"
#include "sanitizer_build.hpp"

namespace ar = attiguard::reach;
using attiguard::test::pd_loop;
using attiguard::test::pd_set;

namespace {

ar::Vec3 in_ball(std::mt19937_64& g, double radius) {
  std::normal_distribution<double> n(0.0, 1.0);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const ar::Vec3 d = ar::Vec3(n(g), n(g), n(g)).normalized();
  return radius * std::cbrt(u(g)) * d;
}

bool in_cell(const ar::InitialSet& c, const ar::Mat3& R, const ar::Vec3& w) {
  return attiguard::lie::distance(c.R0, R) <= c.attitude_radius * (1 + 1e-12) + 1e-15 &&
         (w - c.omega0).norm() <= c.omega_radius * (1 + 1e-12) + 1e-15;
}

/// The hold-interval set of examples/conreach_hold_too_large.toml, its loop and cone.
struct Hold {
  ar::PdLoop loop{ar::Vec3(1.0, 2.0, 3.0).asDiagonal(), 5.0, 1.0,
                  attiguard::lie::quat_to_rotation(Eigen::Vector4d(0.9831359281782146, -0.00038682321939542485,
                                                                   0.1828758923698861, 7.129428627464526e-05))};
  ar::InitialSet set{attiguard::lie::quat_to_rotation(Eigen::Vector4d(0.9843211460246649, -0.00038304706160954767,
                                                                      0.17107644332769953, 0.04294863562423572)),
                     0.08, ar::Vec3(0.028316037439058653, 0.04760989457583405, 0.10238478199401267), 0.08};
  ar::SafetySpec spec;
  Hold() {
    ar::PointingCone c;
    c.name = "pointing";
    c.axis_b = ar::Vec3(0.0, 0.0, 1.0);
    c.direction_i = ar::Vec3(-0.791, 0.061, -0.609).normalized();
    c.half_angle = 160.0 * M_PI / 180.0;
    c.keep_out = false;
    spec.cones.push_back(c);
  }
};

ar::ConReachSettings hold_settings() {
  ar::ConReachSettings s;
  s.metric = ar::MetricKind::coupled;
  s.horizon = 0.5;
  s.steps = 10;
  return s;
}

}  // namespace

TEST(ReachAutoSplit, TheChildrenCoverTheirParent) {
  const ar::InitialSet parent{attiguard::lie::exp(ar::Vec3(0.3, -0.2, 0.1)), 0.2, ar::Vec3(0.1, 0.0, -0.1), 0.05};
  std::mt19937_64 g(7);
  for (const bool attitude : {true, false}) {
    const std::vector<ar::InitialSet> kids = ar::split_cell(parent, attitude);
    ASSERT_EQ(kids.size(), 27U);
    for (const ar::InitialSet& k : kids) {
      EXPECT_NEAR(attitude ? k.attitude_radius : k.omega_radius,
                  (attitude ? parent.attitude_radius : parent.omega_radius) / std::sqrt(3.0), 1e-12);
      EXPECT_EQ(attitude ? k.omega_radius : k.attitude_radius,
                attitude ? parent.omega_radius : parent.attitude_radius);
    }
    for (int s = 0; s < 20000; ++s) {
      const ar::Mat3 R = parent.R0 * attiguard::lie::exp(in_ball(g, parent.attitude_radius));
      const ar::Vec3 w = parent.omega0 + in_ball(g, parent.omega_radius);
      bool covered = false;
      for (const ar::InitialSet& k : kids) covered = covered || in_cell(k, R, w);
      ASSERT_TRUE(covered) << "sample " << s << (attitude ? " (attitude split)" : " (omega split)");
    }
  }
}

TEST(ReachAutoSplit, TheBallWithTheLargerCoverRadiusIsSplit) {
  const ar::ReachResult none;  // no step carried: diag(I, P0)
  EXPECT_TRUE(ar::split_attitude_first({ar::Mat3::Identity(), 0.1, ar::Vec3::Zero(), 0.01}, none));
  EXPECT_FALSE(ar::split_attitude_first({ar::Mat3::Identity(), 0.01, ar::Vec3::Zero(), 0.1}, none));
  EXPECT_FALSE(ar::split_attitude_first({ar::Mat3::Identity(), 0.0, ar::Vec3::Zero(), 0.1}, none));
  EXPECT_TRUE(ar::split_attitude_first({ar::Mat3::Identity(), 0.1, ar::Vec3::Zero(), 0.0}, none));
}

TEST(ReachAutoSplit, ACellWhoseOwnNominalViolatesIsNotSplit) {
  // A keep-out cone around the body z axis's direction at t = 1 s of the PD example's nominal.
  ar::Mat3 R1 = ar::Mat3::Identity();
  ar::simulate(pd_loop(), pd_set().R0, pd_set().omega0, {1.0}, 1e-3,
               [&](std::size_t, const ar::Mat3& R, const ar::Vec3&) { R1 = R; });
  ar::SafetySpec spec;
  ar::PointingCone c;
  c.name = "on_the_path";
  c.axis_b = ar::Vec3(0.0, 0.0, 1.0);
  c.direction_i = R1 * c.axis_b;
  c.half_angle = 0.01;
  c.keep_out = true;
  spec.cones.push_back(c);
  std::string where;
  ASSERT_TRUE(ar::nominal_violates(pd_loop(), pd_set(), 2.0, spec, where));
  EXPECT_NE(where.find("cone 'on_the_path' at t = "), std::string::npos) << where;
  ar::ConReachSettings s;
  s.metric = ar::MetricKind::coupled;
  s.horizon = 2.0;
  s.steps = 20;
  const ar::SplitOutcome out = ar::run_with_splitting(pd_loop(), {pd_set()}, s, spec, {}, 1);
  EXPECT_EQ(out.cells.size(), 1U);
  EXPECT_EQ(out.report.nominal_violations, 1);
  EXPECT_EQ(out.report.cells_split, 0);
  EXPECT_EQ(out.report.leaves_unproved, 1);
  EXPECT_FALSE(out.results[0].complete);  // ended at its first unproved segment
}

TEST(ReachAutoSplit, TheBudgetEndsTheSplittingAndSaysWhich) {
  const Hold hold;
  ar::SplitSettings split;
  split.max_cell_steps = 50;  // the single ball's 10 steps, then 27 cells would need ~270
  const ar::SplitOutcome out = ar::run_with_splitting(hold.loop, {hold.set}, hold_settings(), hold.spec, split, 1);
  EXPECT_TRUE(out.report.budget_spent);
  EXPECT_NE(out.report.budget_reason.find("max_cell_steps = 50"), std::string::npos) << out.report.budget_reason;
  EXPECT_EQ(out.cells.size(), 1U);
  EXPECT_EQ(out.report.leaves_unproved, 1);
  EXPECT_FALSE(ar::verify_safety(hold.spec, out.results).proved);
}

TEST(ReachAutoSplit, TheTimeBudgetStopsACellAfterItsStepAndSaysSo) {
  const Hold hold;
  ar::SplitSettings split;
  split.max_seconds = 1e-9;  // past before the first step ends
  const ar::SplitOutcome out = ar::run_with_splitting(hold.loop, {hold.set}, hold_settings(), hold.spec, split, 1);
  ASSERT_EQ(out.cells.size(), 1U);
  const ar::ReachResult& res = out.results[0];
  EXPECT_FALSE(res.complete);
  EXPECT_EQ(res.steps.size(), 1U);
  EXPECT_EQ(res.stop_time, res.steps[0].t1);
  EXPECT_EQ(res.stop_reason.rfind("the time budget ran out (max_seconds = ", 0), 0U) << res.stop_reason;
  EXPECT_EQ(out.report.cells_split, 0);
  EXPECT_FALSE(ar::verify_safety(hold.spec, out.results).proved);
}

TEST(ReachAutoSplit, SplittingProvesTheSetThatOneBallCannot) {
  // About 30 s of SDPs in Release: the sanitized build covers the splitting rounds with the
  // budget tests and the corpus dozen instead (sanitizer_build.hpp).
  if (attiguard::test::kSanitizedWorkDivisor > 1) GTEST_SKIP() << "Release only (30 s of SDPs)";
  const Hold hold;
  ar::SplitSettings split;
  split.max_seconds = 3600.0;  // the cell-step budget decides, not the machine's speed
  const ar::SplitOutcome out = ar::run_with_splitting(hold.loop, {hold.set}, hold_settings(), hold.spec, split, 2);
  EXPECT_FALSE(out.report.budget_spent) << out.report.budget_reason;
  EXPECT_GT(out.cells.size(), 1U);
  EXPECT_EQ(out.report.leaves_unproved, 0);
  EXPECT_TRUE(ar::verify_safety(hold.spec, out.results).proved);
  // The leaves cover the set: every sample of it lies in one.
  std::mt19937_64 g(11);
  for (int s = 0; s < 5000; ++s) {
    const ar::Mat3 R = hold.set.R0 * attiguard::lie::exp(in_ball(g, hold.set.attitude_radius));
    const ar::Vec3 w = hold.set.omega0 + in_ball(g, hold.set.omega_radius);
    bool covered = false;
    for (const ar::InitialSet& k : out.cells) covered = covered || in_cell(k, R, w);
    ASSERT_TRUE(covered) << s;
  }
}
