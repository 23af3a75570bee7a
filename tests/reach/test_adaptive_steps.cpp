// Adaptive steps and sub-step bisection of ConReach (docs/reach.md, "Adaptive steps"): the
// restarted nominal is bit for bit the continuous one, a loop without `steps` reaches its
// horizon soundly, a sub-step too long for its a priori enclosure is bisected instead of failing,
// and an interval that cannot be carried ends the analysis with its reason (no exception).

#include <gtest/gtest.h>

#include "attiguard/lie/so3.hpp"
#include "attiguard/reach/conreach.hpp"
#include "attiguard/reach/safety.hpp"
#include "attiguard/reach/simulate.hpp"
#include "attiguard/reach/soundness.hpp"
#include "reach/paper_example.hpp"
#include "reach/pd_example.hpp"

namespace ar = attiguard::reach;
using attiguard::test::pd_loop;
using attiguard::test::pd_set;
using attiguard::test::paper_loop;
using attiguard::test::paper_set;

namespace {

/// Sampled soundness of a result (every sampled trajectory inside its balls, tube and U_i).
void expect_sound(const ar::ClosedLoop& loop, const ar::InitialSet& set, const ar::ReachResult& res) {
  ar::SoundnessSettings snd;
  snd.samples = 300;
  snd.step = 1e-3;
  const ar::SoundnessReport rep = ar::check_soundness(loop, set, {set}, {res}, snd);
  EXPECT_EQ(rep.inside, rep.samples);
  EXPECT_EQ(rep.tube_inside, rep.samples) << rep.tube_max_excess;
}

}  // namespace

TEST(ReachAdaptiveSteps, ARestartedNominalIsBitForBitTheContinuousOne) {
  const std::vector<double> times{0.0, 0.1, 0.2, 0.35};
  std::vector<ar::Mat3> R(times.size());
  std::vector<ar::Vec3> w(times.size());
  ar::simulate(pd_loop(), ar::Mat3::Identity(), ar::Vec3(0.1, -0.05, 0.05), times, 1e-3,
               [&](std::size_t k, const ar::Mat3& Rk, const ar::Vec3& wk) {
                 R[k] = Rk;
                 w[k] = wk;
               });
  const std::vector<double> rest{0.1, 0.2, 0.35};
  ar::simulate_from(pd_loop(), 0.1, R[1], w[1], rest, 1e-3,
                    [&](std::size_t k, const ar::Mat3& Rk, const ar::Vec3& wk) {
                      EXPECT_EQ((Rk - R[k + 1]).cwiseAbs().maxCoeff(), 0.0) << k;
                      EXPECT_EQ((wk - w[k + 1]).cwiseAbs().maxCoeff(), 0.0) << k;
                    });
}

TEST(ReachAdaptiveSteps, WithoutStepsThePdLoopReachesItsHorizonSoundly) {
  ar::ConReachSettings s;
  s.metric = ar::MetricKind::coupled;
  s.horizon = 2.0;
  s.adaptive = true;
  s.integrator_step = 0.0;  // derived from the loop
  const ar::ReachResult res = ar::run_conreach(pd_loop(), pd_set(), s);
  ASSERT_TRUE(res.complete) << res.stop_reason;
  ASSERT_FALSE(res.steps.empty());
  EXPECT_DOUBLE_EQ(res.steps.back().t1, 2.0);
  const double lambda = ar::loop_rate_scale(pd_loop(), pd_set());
  EXPECT_GT(lambda, 1.0);  // k_d/J of the fastest axis is 3 /s
  EXPECT_LE(res.steps.front().t1, 0.3 / lambda * (1.0 + 1e-12));  // the first step, or a half of it
  for (std::size_t i = 1; i < res.steps.size(); ++i) EXPECT_EQ(res.steps[i].t0, res.steps[i - 1].t1);
  expect_sound(pd_loop(), pd_set(), res);
}

TEST(ReachAdaptiveSteps, ASubStepTooLongForItsEnclosureIsBisectedInsteadOfFailing) {
  // One sub-step of 1 s on the paper's loop (rates up to 3 /s): the Picard iteration of the a
  // priori enclosure diverges over it. Without bisection the analysis stops there with the
  // reason; with it the sub-step is halved until it holds and the result is sound.
  ar::ConReachSettings s;
  s.horizon = 2.0;
  s.steps = 2;
  s.substeps = 1;
  s.integrator_step = 1e-3;
  s.max_bisections = 0;
  const ar::ReachResult stopped = ar::run_conreach(paper_loop(), paper_set(), s);
  ASSERT_FALSE(stopped.complete);
  EXPECT_EQ(stopped.stop_time, 0.0);
  EXPECT_NE(stopped.stop_reason.find("no a priori enclosure over [0, 1] s"), std::string::npos)
      << stopped.stop_reason;
  const ar::SafetyVerdict v = ar::verify_safety({}, {stopped});
  EXPECT_FALSE(v.proved);
  EXPECT_EQ(v.first_failure_time, 0.0);

  s.max_bisections = 6;
  const ar::ReachResult res = ar::run_conreach(paper_loop(), paper_set(), s);
  ASSERT_TRUE(res.complete) << res.stop_reason;
  EXPECT_GT(res.bisections, 0);
  EXPECT_EQ(res.nominal.size(), res.steps[0].state_tube.size() + res.steps[1].state_tube.size() + 1);
  EXPECT_EQ(res.nominal.back().t, 2.0);
  expect_sound(paper_loop(), paper_set(), res);
}
