// Reproduction of the paper's Sec. 6 results and soundness of the example (≥ 10⁴ samples).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "attiguard/reach/conreach.hpp"
#include "attiguard/reach/contraction_sdp.hpp"
#include "attiguard/reach/metrics.hpp"
#include "attiguard/reach/soundness.hpp"
#include "reach/paper_example.hpp"

namespace ar = attiguard::reach;

using attiguard::test::paper_loop;
using attiguard::test::paper_set;

namespace {

/// The exact ω tube over [t0, t1] of ω̇ = Jω from the ball B(ω0, 0.1) (all components stay
/// positive, each decays monotonically): [e^{J_k t1}(ω0_k − 0.1), e^{J_k t0}(ω0_k + 0.1)].
ar::Box3 exact_tube(double t0, double t1) {
  const ar::Vec3 J(-2, -1, -3);
  const ar::Vec3 w0(0.65, 0.54, 0.61);
  ar::Box3 b;
  for (int k = 0; k < 3; ++k) {
    b.lo(k) = std::exp(J(k) * t1) * (w0(k) - 0.1);
    b.hi(k) = std::exp(J(k) * t0) * (w0(k) + 0.1);
  }
  return b;
}

const ar::ReachResult& paper_result() {
  static const ar::ReachResult res = ar::run_conreach(paper_loop(), paper_set(), {});
  return res;
}
}  // namespace

TEST(ReachPaper, IdentityMetricRateIs0_2071) {
  const ar::LmiEnclosure enc = paper_loop().lmi_enclosure({}, exact_tube(0.0, 0.1));
  EXPECT_NEAR(ar::identity_metric_rate(enc), 0.5 * (std::sqrt(2.0) - 1.0), 1e-12);
}

TEST(ReachPaper, Step0MetricMatchesEquation29) {
  // c = 0.1871 over the paper's U_0, Q_0 = P_0 = I.
  const ar::Box3 U0{ar::Vec3(0.442, 0.398, 0.361), ar::Vec3(0.750, 0.640, 0.710)};
  const ar::LmiEnclosure enc = paper_loop().lmi_enclosure({}, U0);
  const ar::MetricSolution sol = ar::solve_metric(enc, ar::Mat3::Identity(), ar::Mat3::Identity(),
                                                  0.1871, ar::MetricObjective::max_trace_q, {});
  ASSERT_TRUE(sol.ok) << sol.message;
  ar::Mat3 Q1;
  Q1 << 0.989, -0.020, 0.010, -0.020, 0.962, 0.019, 0.010, 0.019, 0.991;
  EXPECT_LT((sol.Q - Q1).cwiseAbs().maxCoeff(), 0.005) << sol.Q;
  std::printf("[ measured ] step 0: max |Q - Q1(29)| = %.4f\n", (sol.Q - Q1).cwiseAbs().maxCoeff());
  EXPECT_NEAR(sol.c, 0.1871, 1e-9);
  EXPECT_LE(sol.worst_eigenvalue, 0.0);
}

TEST(ReachPaper, EnclosuresU0U6ContainTheExactTubeAndAreNoLooserThanThePaper) {
  const ar::ReachResult& res = paper_result();
  ASSERT_EQ(res.steps.size(), 40u);
  // Paper (Sec. 6), printed to 3 decimals: compare up to half a unit of the last digit.
  const ar::Box3 paper0{ar::Vec3(0.442, 0.398, 0.361), ar::Vec3(0.750, 0.640, 0.710)};
  const ar::Box3 paper6{ar::Vec3(0.110, 0.218, 0.025), ar::Vec3(0.250, 0.351, 0.155)};
  const struct { int i; ar::Box3 paper; } cases[] = {{0, paper0}, {6, paper6}};
  for (const auto& c : cases) {
    const ar::ReachStep& st = res.steps[static_cast<std::size_t>(c.i)];
    const ar::Box3 exact = exact_tube(st.t0, st.t1);
    EXPECT_TRUE(st.omega_box.contains(exact)) << "U_" << c.i << " " << st.omega_box.lo.transpose()
                                              << " / " << st.omega_box.hi.transpose();
    EXPECT_TRUE(c.paper.contains(st.omega_box, 5e-4)) << "U_" << c.i << " " << st.omega_box.lo.transpose()
                                                     << " / " << st.omega_box.hi.transpose();
  }
}

TEST(ReachPaper, LineSearchSettlesAt0_1871AndBallsStayPositiveDefinite) {
  const ar::ReachResult& res = paper_result();
  EXPECT_NEAR(res.steps[0].c, 0.1871, 1e-4);
  EXPECT_NEAR(res.steps[6].c, 0.1871, 1e-4);
  for (const ar::ReachStep& st : res.steps) {
    EXPECT_FALSE(st.fallback);
    EXPECT_TRUE(st.lmi_exact);
    EXPECT_GE(st.Q.diagonal().minCoeff(), 0.01);
    EXPECT_GE(st.P.diagonal().minCoeff(), 0.01);
    EXPECT_GT(st.r, 0.0);
  }
  EXPECT_EQ(res.sdp_solves, 120);
}

TEST(ReachPaper, SoundnessTenThousandSamples) {
  const ar::ReachResult& res = paper_result();
  ar::SoundnessSettings s;
  s.samples = 10000;
  s.seed = 7;
  const ar::SoundnessReport rep = ar::check_soundness(paper_loop(), paper_set(), {paper_set()}, {res}, s);
  EXPECT_EQ(rep.samples, 10000);
  EXPECT_EQ(rep.inside, rep.samples) << "first violation at t = " << rep.first_violation_time;
  EXPECT_LE(rep.max_ratio, 1.0 + 1e-12);
}

TEST(ReachPaper, MinEnclosureModeIsSoundAndNoWorse) {
  ar::ConReachSettings s;
  s.mode = ar::RateMode::min_enclosure;
  const ar::ReachResult res = ar::run_conreach(paper_loop(), paper_set(), s);
  const auto enclosure = [](const ar::ReachStep& st) {
    return st.r / std::sqrt(std::min(ar::lambda_min(st.Q), ar::lambda_min(st.P)));
  };
  EXPECT_LE(enclosure(res.steps.back()), enclosure(paper_result().steps.back()) * (1 + 1e-9));
  ar::SoundnessSettings ss;
  ss.samples = 2000;
  const ar::SoundnessReport rep = ar::check_soundness(paper_loop(), paper_set(), {paper_set()}, {res}, ss);
  EXPECT_EQ(rep.inside, rep.samples);
}
