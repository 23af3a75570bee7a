// ConReach on a PD closed loop (robust LMI over interval enclosures), partitioning, safety.

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "attiguard/reach/conreach.hpp"
#include "attiguard/reach/contraction_sdp.hpp"
#include "attiguard/reach/partition.hpp"
#include "attiguard/reach/safety.hpp"
#include "attiguard/reach/soundness.hpp"
#include "reach/pd_example.hpp"
#include "test_support.hpp"

namespace ar = attiguard::reach;
using attiguard::lie::exp;

namespace {
using attiguard::test::pd_loop;
using attiguard::test::pd_set;
ar::ConReachSettings pd_settings() {
  ar::ConReachSettings s;
  s.horizon = 2.0;
  s.steps = 20;
  return s;
}
const ar::ReachResult& pd_result() {
  static const ar::ReachResult res = ar::run_conreach(pd_loop(), pd_set(), pd_settings());
  return res;
}
}  // namespace

TEST(ReachPd, RobustLmiHoldsAtSampledStatesOfEveryEnclosure) {
  const ar::ReachResult& res = pd_result();
  for (const ar::ReachStep& st : res.steps) {
    EXPECT_FALSE(st.lmi_exact);
    EXPECT_GT(st.lmi_rho, 0.0);
    for (int k = 0; k < 200; ++k) {
      const ar::Mat3 R = st.attitude_box.center * exp(attiguard::test::random_vector_in_ball(st.attitude_box.radius));
      ar::Vec3 w;
      for (int j = 0; j < 3; ++j) {
        w(j) = st.omega_box.lo(j) + (st.omega_box.hi(j) - st.omega_box.lo(j)) * (0.5 + 0.5 * ar::Vec3::Random()(0));
      }
      const ar::Mat6 M = ar::contraction_lmi(st.Q, st.P, pd_loop().A(R, w), pd_loop().B(R, w), w, st.c);
      Eigen::SelfAdjointEigenSolver<ar::Mat6> es(M, Eigen::EigenvaluesOnly);
      ASSERT_LE(es.eigenvalues()(5), 1e-9) << "step " << st.index;
    }
  }
}

TEST(ReachPd, SoundnessTenThousandSamples) {
  ar::SoundnessSettings s;
  s.samples = 10000;
  s.seed = 11;
  const ar::SoundnessReport rep = ar::check_soundness(pd_loop(), pd_set(), {pd_set()}, {pd_result()}, s);
  EXPECT_EQ(rep.samples, 10000);
  EXPECT_EQ(rep.inside, rep.samples) << "first violation at t = " << rep.first_violation_time;
}

TEST(ReachPd, PartitionedRunIsSound) {
  ar::ConReachSettings s = pd_settings();
  s.horizon = 1.0;
  s.steps = 10;
  const ar::InitialSet whole{ar::Mat3::Identity(), 0.08, ar::Vec3(0.1, -0.05, 0.05), 0.08};
  const auto cells = ar::partition_initial_set(whole, 2, 1);
  const auto results = ar::run_partitioned(pd_loop(), cells, s, 2);
  ASSERT_EQ(results.size(), cells.size());
  ar::SoundnessSettings ss;
  ss.samples = 1000;
  const ar::SoundnessReport rep = ar::check_soundness(pd_loop(), whole, cells, results, ss);
  EXPECT_EQ(rep.inside, rep.samples);
}

TEST(ReachSafety, ProvesFarConesAndReportsTheFirstUnprovableTime) {
  const ar::ReachResult& res = pd_result();
  ar::SafetySpec far;
  far.cones.push_back({"far", ar::Vec3::UnitZ(), -ar::Vec3::UnitZ(), 0.5, true});
  far.omega_norm_max = 5.0;
  const ar::SafetyVerdict ok = ar::verify_safety(far, {res});
  EXPECT_TRUE(ok.requested);
  EXPECT_TRUE(ok.proved);
  EXPECT_LT(ok.first_failure_time, 0.0);

  // The body x axis turns towards the reference (20° about z): a keep-out cone around
  // R_g e_x cannot be proved once the tube reaches it; an ω bound below ‖ω0‖ fails at t = 0.
  ar::SafetySpec near;
  near.cones.push_back({"target", ar::Vec3::UnitX(), exp(ar::Vec3(0, 0, 20.0 * M_PI / 180.0)) * ar::Vec3::UnitX(),
                        10.0 * M_PI / 180.0, true});
  const ar::SafetyVerdict bad = ar::verify_safety(near, {res});
  EXPECT_FALSE(bad.proved);
  EXPECT_GT(bad.first_failure_time, 0.0);
  EXPECT_NE(bad.reason.find("target"), std::string::npos);
  ar::SafetySpec slow;
  slow.omega_norm_max = 0.05;
  const ar::SafetyVerdict v = ar::verify_safety(slow, {res});
  EXPECT_FALSE(v.proved);
  EXPECT_DOUBLE_EQ(v.first_failure_time, 0.0);
}
