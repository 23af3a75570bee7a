// The interval-arithmetic proof of the contraction LMI and of the metric bounds
// (reach/lmi_proof.hpp): it accepts what holds with a margin above rounding and refuses a
// solution perturbed by 1e-9 towards infeasibility.

#include <gtest/gtest.h>

#include "attiguard/reach/contraction_sdp.hpp"
#include "attiguard/reach/lmi_proof.hpp"
#include "attiguard/reach/metrics.hpp"
#include "test_support.hpp"

namespace ar = attiguard::reach;
using attiguard::test::random_rotation;

TEST(ReachLmiProof, NegativeDefinitenessIsProvedAboveRoundingAndRefusedBelowZero) {
  for (int trial = 0; trial < 50; ++trial) {
    const ar::Mat3 V = random_rotation();
    const ar::Mat3 good = V * ar::Vec3(-1.0, -2.0, -1e-12).asDiagonal() * V.transpose();
    const ar::Mat3 bad = V * ar::Vec3(-1.0, -2.0, 1e-14).asDiagonal() * V.transpose();
    EXPECT_TRUE(ar::prove_less(good, ar::Mat3::Zero()).proved) << good;
    EXPECT_FALSE(ar::prove_less(bad, ar::Mat3::Zero()).proved) << bad;
    // Q ≺ Q_prev with the two equal: not provable (the certification scales Q down first).
    EXPECT_FALSE(ar::prove_less(V, V).proved);
  }
}

TEST(ReachLmiProof, CatchesAnSdpSolutionPerturbedBy1e9TowardsInfeasibility) {
  // The paper's step 0 (Sec. 6): linear ω-dynamics diag(−2, −1, −3) over its U_0.
  const ar::LinearOmegaLoop loop(ar::Vec3(-2, -1, -3).asDiagonal());
  const ar::Box3 U0{ar::Vec3(0.442, 0.398, 0.361), ar::Vec3(0.750, 0.640, 0.710)};
  const ar::LmiEnclosure enc = loop.lmi_enclosure({}, U0);
  const ar::MetricSolution sol = ar::solve_metric(enc, ar::Mat3::Identity(), ar::Mat3::Identity(),
                                                  0.1871, ar::MetricObjective::max_trace_q, {});
  ASSERT_TRUE(sol.ok) << sol.message;
  const ar::NegativeDefiniteProof at_certified = ar::prove_contraction_lmi(enc, sol.Q, sol.P, sol.c, {});
  EXPECT_TRUE(at_certified.proved);
  EXPECT_LT(at_certified.margin, 0.0);
  // Lower c until the (double-precision) worst eigenvalue of the LMI is +1e-9: M grows by
  // 2Δc·diag(Q, P), so Δc = (worst + 1e-9)/(2 λ_min).
  const double lmin = std::min(ar::lambda_min(sol.Q), ar::lambda_min(sol.P));
  const double worst = ar::lmi_worst_eigenvalue(enc, sol.Q, sol.P, sol.c, {});
  double c_bad = sol.c - (1e-9 - worst) / (2.0 * lmin);
  for (int it = 0; it < 20 && ar::lmi_worst_eigenvalue(enc, sol.Q, sol.P, c_bad, {}) < 1e-9; ++it) {
    c_bad -= 1e-10 / lmin;
  }
  ASSERT_GE(ar::lmi_worst_eigenvalue(enc, sol.Q, sol.P, c_bad, {}), 1e-9);
  EXPECT_FALSE(ar::prove_contraction_lmi(enc, sol.Q, sol.P, c_bad, {}).proved);
  // And a metric perturbed by 1e-9 above the previous one is refused by the monotonicity proof.
  const ar::Mat3 Q_up = ar::Mat3::Identity() + 1e-9 * ar::Mat3::Ones();
  EXPECT_FALSE(ar::prove_less(Q_up, ar::Mat3::Identity()).proved);
}

TEST(ReachLmiProof, RobustFormNeedsPositiveMultipliers) {
  ar::LmiEnclosure enc;
  enc.rho = 0.1;
  enc.vertices.push_back({ar::Vec3(0.1, 0.2, 0.3), ar::Mat3::Zero(), -ar::Mat3::Identity()});
  EXPECT_FALSE(ar::prove_contraction_lmi(enc, ar::Mat3::Identity(), ar::Mat3::Identity(), 0.0, {0.0}).proved);
  // Q = P = I, A = 0, B = −I: M = [[−2cI, I], [I, −(2 + 2c)I]]; with μ = 1 the robust matrix adds
  // μρ²I = 0.01I and PPᵀ/μ = I to the lower block: at c = 2, [[−3.99I, I], [I, −4.99I]] ≺ 0.
  EXPECT_TRUE(ar::prove_contraction_lmi(enc, ar::Mat3::Identity(), ar::Mat3::Identity(), 2.0, {1.0}).proved);
}
