// Exact round trip of ConReach results through the CBOR codec that carries partition cells
// between MPI ranks (reach/result_codec.hpp): decoding gives back every bit.

#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "attiguard/core/errors.hpp"
#include "attiguard/reach/conreach.hpp"
#include "attiguard/reach/result_codec.hpp"
#include "test_support.hpp"

namespace ar = attiguard::reach;

namespace {

template <class M>
bool same_bits(const M& a, const M& b) {
  return a.size() == b.size() &&
         std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(a.size())) == 0;
}

ar::ReachResult codec_pd_result() {
  const ar::PdLoop loop(ar::Vec3(1.0, 2.0, 3.0).asDiagonal(), 2.0, 3.0,
                        attiguard::lie::exp(ar::Vec3(0.0, 0.0, 0.3)));
  const ar::InitialSet set{attiguard::lie::exp(ar::Vec3(0.1, -0.2, 0.05)), 0.03,
                           ar::Vec3(0.1, -0.05, 0.05), 0.02};
  ar::ConReachSettings s;
  s.horizon = 0.5;
  s.steps = 5;
  return ar::run_conreach(loop, set, s);
}

}  // namespace

TEST(ReachResultCodec, RoundTripKeepsEveryBit) {
  const ar::ReachResult r = codec_pd_result();
  ASSERT_EQ(r.steps.size(), 5u);
  ASSERT_FALSE(r.steps.front().state_tube.empty());
  ASSERT_FALSE(r.steps.front().trials.empty());
  const std::string bytes = ar::encode_result(r);
  const ar::ReachResult d = ar::decode_result(bytes);

  EXPECT_TRUE(same_bits(d.initial.R0, r.initial.R0));
  EXPECT_EQ(d.initial.attitude_radius, r.initial.attitude_radius);
  EXPECT_TRUE(same_bits(d.initial.omega0, r.initial.omega0));
  EXPECT_TRUE(same_bits(d.Q0, r.Q0));
  EXPECT_TRUE(same_bits(d.P0, r.P0));
  EXPECT_EQ(d.r0, r.r0);
  EXPECT_EQ(d.sdp_solves, r.sdp_solves);
  EXPECT_EQ(d.complete, r.complete);
  EXPECT_EQ(d.stop_time, r.stop_time);
  EXPECT_EQ(d.stop_reason, r.stop_reason);
  EXPECT_EQ(d.bisections, r.bisections);
  EXPECT_EQ(d.retries, r.retries);
  ar::ReachResult stopped = r;  // a cell that stopped early keeps its reason through the codec
  stopped.complete = false;
  stopped.stop_time = 0.25;
  stopped.stop_reason = "ConReach tube: no a priori enclosure over [0.25, 0.3] s";
  stopped.bisections = 3;
  stopped.retries = 2;
  const ar::ReachResult ds = ar::decode_result(ar::encode_result(stopped));
  EXPECT_FALSE(ds.complete);
  EXPECT_EQ(ds.stop_time, 0.25);
  EXPECT_EQ(ds.stop_reason, stopped.stop_reason);
  EXPECT_EQ(ds.bisections, 3);
  EXPECT_EQ(ds.retries, 2);
  ASSERT_EQ(d.nominal.size(), r.nominal.size());
  for (std::size_t i = 0; i < r.nominal.size(); ++i) {
    EXPECT_EQ(d.nominal[i].t, r.nominal[i].t);
    EXPECT_TRUE(same_bits(d.nominal[i].R, r.nominal[i].R));
    EXPECT_TRUE(same_bits(d.nominal[i].omega, r.nominal[i].omega));
  }
  ASSERT_EQ(d.steps.size(), r.steps.size());
  for (std::size_t i = 0; i < r.steps.size(); ++i) {
    const ar::ReachStep& a = r.steps[i];
    const ar::ReachStep& b = d.steps[i];
    EXPECT_EQ(b.index, a.index);
    EXPECT_EQ(b.t0, a.t0);
    EXPECT_EQ(b.t1, a.t1);
    EXPECT_EQ(b.c, a.c);
    EXPECT_EQ(b.c_identity, a.c_identity);
    EXPECT_EQ(b.r, a.r);
    EXPECT_TRUE(same_bits(b.Q, a.Q));
    EXPECT_TRUE(same_bits(b.P, a.P));
    EXPECT_TRUE(same_bits(b.R, a.R));
    EXPECT_TRUE(same_bits(b.omega_box.lo, a.omega_box.lo));
    EXPECT_TRUE(same_bits(b.omega_box.hi, a.omega_box.hi));
    EXPECT_EQ(b.attitude_box.radius, a.attitude_box.radius);
    EXPECT_EQ(b.attitude_radius, a.attitude_radius);
    EXPECT_EQ(b.lmi_exact, a.lmi_exact);
    EXPECT_EQ(b.fallback, a.fallback);
    ASSERT_EQ(b.state_tube.size(), a.state_tube.size());
    EXPECT_EQ(b.state_tube.back().attitude.radius, a.state_tube.back().attitude.radius);
    EXPECT_TRUE(same_bits(b.state_tube.back().omega.hi, a.state_tube.back().omega.hi));
    ASSERT_EQ(b.trials.size(), a.trials.size());
    EXPECT_EQ(b.trials.front().c, a.trials.front().c);
    EXPECT_EQ(b.trials.front().feasible, a.trials.front().feasible);
  }
  // Encoding the decoded result gives the same bytes: nothing was lost or added.
  EXPECT_EQ(ar::encode_result(d), bytes);
}

TEST(ReachResultCodec, MalformedBytesAreANumericalErrorNotACrash) {
  const std::string bytes = ar::encode_result(codec_pd_result());
  EXPECT_THROW((void)ar::decode_result(bytes.substr(0, bytes.size() / 2)), attiguard::NumericalError);
  EXPECT_THROW((void)ar::decode_result("not cbor"), attiguard::NumericalError);
}
