// The ω-norm bound of a tube segment (tube.hpp, step 3; docs/reach.md "Enclosure U_i"):
// max‖ω*‖ over the tent of x* plus the sup of e_ω, tighter than the corner of the ω box and
// still above every sampled trajectory.

#include <gtest/gtest.h>

#include "attiguard/reach/conreach.hpp"
#include "attiguard/reach/safety.hpp"
#include "attiguard/reach/soundness.hpp"
#include "reach/pd_example.hpp"

namespace ar = attiguard::reach;
using attiguard::test::pd_loop;
using attiguard::test::pd_set;

TEST(ReachTubeNorm, TheOmegaNormBoundIsTighterThanTheBoxAndHoldsOnSamples) {
  ar::ConReachSettings s;
  s.metric = ar::MetricKind::coupled;
  s.horizon = 1.0;
  s.steps = 10;
  const ar::ReachResult res = ar::run_conreach(pd_loop(), pd_set(), s);
  ASSERT_TRUE(res.complete);
  const ar::TubeSegment& first = res.steps.front().state_tube.front();
  // At t = 0 the set's ω ball: ‖ω‖ ≤ ‖ω0‖ + b, while the box's corner reaches ‖|ω0| + b·1‖.
  const double ball = pd_set().omega0.norm() + pd_set().omega_radius;
  EXPECT_LT(first.omega_norm_bound(), first.omega.norm_max());
  EXPECT_LT(first.omega_norm_bound(), 1.2 * ball);
  for (const ar::ReachStep& st : res.steps) {
    for (const ar::TubeSegment& seg : st.state_tube) EXPECT_LE(seg.omega_norm_bound(), seg.omega.norm_max());
  }
  // A bound between the two: proved with the norm bound, not with the box's corner.
  ar::SafetySpec spec;
  spec.omega_norm_max = 0.5 * (first.omega_norm_bound() + first.omega.norm_max());
  double worst = 0.0;
  for (const ar::ReachStep& st : res.steps) {
    for (const ar::TubeSegment& seg : st.state_tube) worst = std::max(worst, seg.omega_norm_bound());
  }
  if (worst < *spec.omega_norm_max) {
    EXPECT_TRUE(ar::verify_safety(spec, {res}).proved);
  }
  // Every sampled trajectory respects the bound (check_soundness counts it in tube_inside).
  ar::SoundnessSettings snd;
  snd.samples = 500;
  snd.step = 1e-3;
  const ar::SoundnessReport rep = ar::check_soundness(pd_loop(), pd_set(), {pd_set()}, {res}, snd);
  EXPECT_EQ(rep.tube_inside, rep.samples) << rep.tube_max_excess;
}
