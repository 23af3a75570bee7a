// The sampled soundness check (reach/soundness.hpp) looks at the state-tube segments and U_i too,
// not only at the balls at t_i: a face moved inwards is caught.

#include <gtest/gtest.h>

#include "attiguard/reach/conreach.hpp"
#include "attiguard/reach/soundness.hpp"
#include "reach/paper_example.hpp"

namespace ar = attiguard::reach;

namespace {
struct Fixture : attiguard::test::PaperReach {
  ar::SoundnessSettings settings;
  Fixture() : PaperReach(0.5, 5) {
    settings.samples = 400;
    settings.threads = 1;
  }
  ar::SoundnessReport check() const { return ar::check_soundness(loop, initial, {initial}, {result}, settings); }
};
}  // namespace

TEST(ReachSoundness, TubeAndBoxesOfTheTrueResultContainEverySample) {
  const Fixture f;
  const ar::SoundnessReport rep = f.check();
  EXPECT_EQ(rep.inside, rep.samples);
  EXPECT_EQ(rep.tube_inside, rep.samples);
  EXPECT_EQ(rep.tube_max_excess, 0.0);
}

TEST(ReachSoundness, CatchesASegmentFaceMovedInwards) {
  Fixture f;
  ar::TubeSegment& seg = f.result.steps[2].state_tube[4];
  seg.omega.hi(0) -= 0.5 * (seg.omega.hi(0) - seg.omega.lo(0));
  const ar::SoundnessReport rep = f.check();
  EXPECT_EQ(rep.inside, rep.samples);  // the balls are untouched
  EXPECT_LT(rep.tube_inside, rep.samples);
  EXPECT_GT(rep.tube_max_excess, 0.0);
  EXPECT_NEAR(rep.tube_first_violation_time, seg.t0, 1e-12);
}

TEST(ReachSoundness, CatchesAnOmegaBoxUiFaceMovedInwards) {
  Fixture f;
  ar::ReachStep& st = f.result.steps[3];
  st.omega_box.lo(2) += 0.5 * (st.omega_box.hi(2) - st.omega_box.lo(2));
  const ar::SoundnessReport rep = f.check();
  EXPECT_LT(rep.tube_inside, rep.samples);
  EXPECT_NEAR(rep.tube_first_violation_time, st.t0, 1e-12);
}

// A stop flag that is set (the program's SIGINT/SIGTERM flag) ends the sampling at the next
// sample: the report says so and counts only the samples it checked.
TEST(ReachSoundness, ASetStopFlagEndsTheSamplingAndTheReportSaysSo) {
  Fixture f;
  const std::atomic<bool> stop{true};
  f.settings.stop = &stop;
  const ar::SoundnessReport rep = f.check();
  EXPECT_TRUE(rep.stopped);
  EXPECT_EQ(rep.samples, 0);
  const std::atomic<bool> go{false};
  f.settings.stop = &go;
  const ar::SoundnessReport full = f.check();
  EXPECT_FALSE(full.stopped);
  EXPECT_EQ(full.samples, 400);
}
