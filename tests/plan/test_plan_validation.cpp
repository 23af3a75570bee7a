// The slew planner against an independent fine-mesh solution (issue 43; docs/slew-planner.md,
// "Validation"): on eight constrained problems across the range of crafts, the Hermite–Simpson
// plan's duration is within 5 % of a trapezoidal transcription of the same problem at 4× the
// intervals, started from the roadmap's path (not from the plan), and both keep every cone and
// ‖τ‖ ≤ τ_max at 100 points per interval. Each problem prints its row of the docs' table.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "attiguard/governor/cone_constraint.hpp"
#include "attiguard/lie/so3.hpp"
#include "attiguard/plan/slew_planner.hpp"
#include "plan/eight_problems.hpp"

namespace attiguard::plan::plan_validation_test {
namespace {


using eight_problems::Case;
using eight_problems::cases;
using eight_problems::kDeg;

/// Every cone kept and ‖τ‖ ≤ τ_max at 100 points per interval.
void expect_admissible(const PlannedSlew& planned, const SlewProblem& p, const std::string& what) {
  const DenseCheck check = dense_check(planned.plan, p, 100);
  if (!p.cones.empty()) {
    EXPECT_GE(check.smallest_cone_margin, 0.0) << what;
  }
  EXPECT_LE(check.largest_torque_ratio, 1.0) << what;
}

class Validation : public ::testing::TestWithParam<int> {};

TEST_P(Validation, PlanIsWithinFivePercentOfAFineTrapezoidalSolutionAndKeepsEveryConstraint) {
  const Case c = cases()[static_cast<std::size_t>(GetParam())];
  const PlannedSlew planned = plan_slew(c.problem);
  expect_admissible(planned, c.problem, c.name + " (plan)");

  PlannerOptions fine;
  fine.transcription = Transcription::trapezoid;
  fine.intervals = 4 * planned.report.intervals;
  fine.max_solve_seconds = 300.0;
  fine.max_iterations = 3000;
  const PlannedSlew reference = plan_slew(c.problem, fine);
  expect_admissible(reference, c.problem, c.name + " (fine mesh)");

  const double difference = planned.report.duration / reference.report.duration - 1.0;
  EXPECT_LE(std::abs(difference), 0.05) << c.name;
  std::printf("| %s | %d | %.6g | %.4f | %d | %.6g | %+.2f %% | %.3f | %.4f | %.3f |\n",
              c.name.c_str(), static_cast<int>(c.problem.cones.size()), planned.report.duration,
              planned.report.ratio, planned.report.intervals, reference.report.duration,
              100.0 * difference, planned.report.check.smallest_cone_margin / kDeg,
              planned.report.check.largest_torque_ratio, planned.report.planning_seconds);
}

INSTANTIATE_TEST_SUITE_P(EightProblems, Validation, ::testing::Range(0, 8));

}  // namespace
}  // namespace attiguard::plan::plan_validation_test
