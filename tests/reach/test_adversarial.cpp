// The adversarial soundness / tightness check (reach/adversarial.hpp).

#include <gtest/gtest.h>

#include "attiguard/reach/adversarial.hpp"
#include "attiguard/reach/metrics.hpp"
#include "reach/paper_example.hpp"

namespace ar = attiguard::reach;

namespace {
struct Paper : attiguard::test::PaperReach {
  Paper() : PaperReach(1.0, 10) {}
};
}  // namespace

TEST(ReachAdversarial, PaperExampleHasNoEscapeAndItsEnclosureIsNoTighterThanTheTruth) {
  const Paper p;
  ar::AdversarialSettings s;
  s.threads = 1;
  const ar::AdversarialReport rep = ar::adversarial_check(p.loop, {p.initial}, {p.result}, s);
  EXPECT_LE(rep.worst_ratio, 1.0 + 1e-12);
  EXPECT_GT(rep.worst_ratio, 0.9);  // the balls are tight for this affine flow
  EXPECT_GE(rep.attitude_claimed, rep.attitude_spread);
  EXPECT_GT(rep.attitude_spread, 0.5 * rep.attitude_claimed);
  for (int k = 0; k < 3; ++k) EXPECT_GE(rep.omega_claimed(k), rep.omega_spread(k));
  EXPECT_EQ(rep.evaluations, 5L * s.starts * (s.iterations + 1));
}

TEST(ReachAdversarial, FindsTheEscapeFromBallsShrunkBy20Percent) {
  Paper p;
  for (ar::ReachStep& st : p.result.steps) st.r *= 0.8;
  ar::AdversarialSettings s;
  s.threads = 1;
  const ar::AdversarialReport rep = ar::adversarial_check(p.loop, {p.initial}, {p.result}, s);
  EXPECT_GT(rep.worst_ratio, 1.1);
  EXPECT_GT(rep.worst_ratio_time, 0.0);
}

// A set stop flag (the program's SIGINT/SIGTERM flag) ends the search before its next start.
TEST(ReachAdversarial, ASetStopFlagEndsTheSearchAndTheReportSaysSo) {
  const Paper p;
  ar::AdversarialSettings s;
  s.threads = 1;
  const std::atomic<bool> stop{true};
  s.stop = &stop;
  const ar::AdversarialReport rep = ar::adversarial_check(p.loop, {p.initial}, {p.result}, s);
  EXPECT_TRUE(rep.stopped);
  EXPECT_EQ(rep.evaluations, 0);
}
