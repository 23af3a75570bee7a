// The coupled left-invariant metric M = [[Q, S], [Sᵀ, P]] on SO(3) × R³ (docs/reach.md, "Coupled
// metrics"): its distance bound and projections (metrics.hpp), the generalised contraction LMI
// and its SDP and interval proof (contraction_sdp.hpp, lmi_proof.hpp), ConReach with it on the PD
// loop (contracting, c < 0, sound), and the `rigour` setting.

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <random>

#include "attiguard/core/errors.hpp"
#include "attiguard/reach/conreach.hpp"
#include "attiguard/reach/safety.hpp"
#include "attiguard/reach/contraction_sdp.hpp"
#include "attiguard/reach/lmi_proof.hpp"
#include "attiguard/reach/metrics.hpp"
#include "attiguard/reach/soundness.hpp"
#include "reach/pd_example.hpp"
#include "sanitizer_build.hpp"
#include "test_support.hpp"

namespace ar = attiguard::reach;
using attiguard::lie::exp;

namespace {

ar::StateMetric random_metric(std::mt19937& g) {
  std::normal_distribution<double> n(0.0, 1.0);
  Eigen::Matrix<double, 6, 6> X;
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) X(i, j) = n(g);
  }
  const ar::Mat6 M = X * X.transpose() + 0.1 * ar::Mat6::Identity();
  return {M.topLeftCorner<3, 3>(), M.topRightCorner<3, 3>(), M.bottomRightCorner<3, 3>()};
}

using attiguard::test::pd_loop;
using attiguard::test::pd_set;
ar::ConReachSettings coupled_settings() {
  ar::ConReachSettings s;
  s.horizon = 2.0;
  s.steps = 20;
  s.metric = ar::MetricKind::coupled;
  return s;
}
const ar::ReachResult& coupled_result() {
  static const ar::ReachResult res = ar::run_conreach(pd_loop(), pd_set(), coupled_settings());
  return res;
}

}  // namespace

TEST(ReachCoupledMetric, SchurComplementsBoundTheQuadraticFormAndTheCoverBoundsTheBox) {
  std::mt19937 g(3);
  std::normal_distribution<double> n(0.0, 1.0);
  for (int trial = 0; trial < 50; ++trial) {
    const ar::StateMetric m = random_metric(g);
    const ar::Mat6 M = ar::metric_matrix(m);
    const ar::Mat3 Qs = ar::attitude_schur(m);
    const ar::Mat3 Ps = ar::omega_schur(m);
    const double a = 0.1 + std::abs(n(g));
    const double b = 0.1 + std::abs(n(g));
    const double cover = ar::metric_cover_radius(m, a, b);
    for (int k = 0; k < 200; ++k) {
      Eigen::Matrix<double, 6, 1> z;
      for (int i = 0; i < 6; ++i) z(i) = n(g);
      const ar::Vec3 al = z.head<3>();
      const ar::Vec3 be = z.tail<3>();
      const double q = z.dot(M * z);
      EXPECT_GE(q, al.dot(Qs * al) * (1.0 - 1e-12) - 1e-12);  // coupled fact 3
      EXPECT_GE(q, be.dot(Ps * be) * (1.0 - 1e-12) - 1e-12);  // coupled fact 2
      // A point of the box ‖α‖ = a, ‖β‖ = b lies within the cover radius (fact 1).
      Eigen::Matrix<double, 6, 1> y;
      y << a * al.normalized(), b * be.normalized();
      EXPECT_LE(std::sqrt(y.dot(M * y)), cover * (1.0 + 1e-12));
    }
    // The distance bound is the same quadratic form on (log(R1ᵀR2), ω2 − ω1).
    const ar::Vec3 w(0.1, -0.2, 0.3);
    const ar::Vec3 v(0.05, 0.0, -0.1);
    Eigen::Matrix<double, 6, 1> z;
    z << w, v;
    EXPECT_NEAR(ar::metric_distance_upper(m, ar::Mat3::Identity(), ar::Vec3::Zero(), exp(w), v),
                std::sqrt(z.dot(M * z)), 1e-12);
  }
}

TEST(ReachCoupledMetric, GeneralLmiIsTheProductLmiWhenSIsZeroAndDifferentiatesTheMetric) {
  std::mt19937 g(5);
  std::normal_distribution<double> n(0.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    const ar::StateMetric m = random_metric(g);
    ar::Mat3 A;
    ar::Mat3 B;
    ar::Vec3 w;
    for (int i = 0; i < 3; ++i) {
      w(i) = n(g);
      for (int j = 0; j < 3; ++j) {
        A(i, j) = n(g);
        B(i, j) = n(g);
      }
    }
    ar::StateMetric prod = m;
    prod.S.setZero();
    EXPECT_LT((ar::contraction_lmi(ar::metric_matrix(prod), A, B, w, 0.3) -
               ar::contraction_lmi(prod.Q, prod.P, A, B, w, 0.3)).norm(), 1e-12);
    // d/dt zᵀMz along ż = Fz, F = [[−ω̂, I], [A, B]], equals zᵀ(L + 2cM)z.
    ar::Mat6 F = ar::Mat6::Zero();
    F.topLeftCorner<3, 3>() = -attiguard::lie::hat(w);
    F.topRightCorner<3, 3>() = ar::Mat3::Identity();
    F.bottomLeftCorner<3, 3>() = A;
    F.bottomRightCorner<3, 3>() = B;
    Eigen::Matrix<double, 6, 1> z;
    for (int i = 0; i < 6; ++i) z(i) = n(g);
    const ar::Mat6 M = ar::metric_matrix(m);
    const double h = 1e-6;
    const Eigen::Matrix<double, 6, 1> zp = z + h * F * z;
    const Eigen::Matrix<double, 6, 1> zm = z - h * F * z;
    const double fd = (zp.dot(M * zp) - zm.dot(M * zm)) / (2.0 * h);
    const double lmi = z.dot((ar::contraction_lmi(M, A, B, w, 0.3) + 0.6 * M) * z);
    EXPECT_NEAR(fd, lmi, 1e-6 * (1.0 + std::abs(lmi)));
  }
}

TEST(ReachCoupledMetric, PdLoopContractsInACoupledMetricWhereTheProductMetricCannot) {
  // The PD loop over a small enclosure: the product metric's best feasible rate is positive,
  // the coupled metric proves a negative one, and the proof refuses it 1e-9 below.
  const ar::LmiEnclosure enc = pd_loop().lmi_enclosure({ar::Mat3::Identity(), 0.05},
                                                       {ar::Vec3(0.05, -0.1, 0.0), ar::Vec3(0.15, 0.0, 0.1)});
  ar::MetricSdpSettings product;
  ar::MetricSdpSettings coupled;
  coupled.coupled = true;
  const ar::StateMetric I{ar::Mat3::Identity(), ar::Mat3::Zero(), ar::Mat3::Identity()};
  EXPECT_FALSE(ar::solve_metric(enc, I, 0.0, ar::MetricObjective::max_min_eigenvalue, product).ok);
  const ar::MetricSolution sol = ar::solve_metric(enc, I, -0.2, ar::MetricObjective::max_min_eigenvalue, coupled);
  ASSERT_TRUE(sol.ok) << sol.message;
  EXPECT_TRUE(sol.proved);
  EXPECT_LT(sol.c, 0.0);
  EXPECT_GT(sol.S.norm(), 1e-3);
  const ar::StateMetric m{sol.Q, sol.S, sol.P};
  const std::vector<double>& mu = sol.mu;
  EXPECT_GT(enc.rho, 0.0);  // the robust form (A depends on R)
  EXPECT_TRUE(ar::prove_contraction_lmi(enc, m, sol.c, mu).proved);
  // Lower c until the worst eigenvalue is +1e-9: L grows by at least 2Δc λ_min(M).
  const Eigen::SelfAdjointEigenSolver<ar::Mat6> es(ar::metric_matrix(m), Eigen::EigenvaluesOnly);
  const double lmin = es.eigenvalues()(0);
  double c_bad = sol.c - (1e-9 - ar::lmi_worst_eigenvalue(enc, m, sol.c, mu)) / (2.0 * lmin);
  for (int it = 0; it < 60 && ar::lmi_worst_eigenvalue(enc, m, c_bad, mu) < 1e-9; ++it) c_bad -= 1e-10 / lmin;
  ASSERT_GE(ar::lmi_worst_eigenvalue(enc, m, c_bad, mu), 1e-9);
  EXPECT_FALSE(ar::prove_contraction_lmi(enc, m, c_bad, mu).proved);
}

TEST(ReachCoupledMetric, ConReachOnThePdLoopHasNegativeRatesAndIsSound) {
  const ar::ReachResult& res = coupled_result();
  ASSERT_EQ(res.steps.size(), 20U);
  for (const ar::ReachStep& st : res.steps) {
    EXPECT_LT(st.c, 0.0) << "step " << st.index;
    EXPECT_TRUE(st.proved_rigorously);
    EXPECT_FALSE(st.fallback);
  }
  // Tighter than the product metric at T (0.364 rad there, docs/reach.md).
  EXPECT_LT(res.steps.back().attitude_radius, 0.1);
  ar::SoundnessSettings s;
  s.samples = attiguard::test::for_this_build(10000, 100);
  s.seed = 13;
  const ar::SoundnessReport rep = ar::check_soundness(pd_loop(), pd_set(), {pd_set()}, {res}, s);
  EXPECT_EQ(rep.inside, rep.samples) << "first violation at t = " << rep.first_violation_time;
  EXPECT_LE(rep.max_ratio, 1.0 + 1e-12);
}

TEST(ReachCoupledMetric, FloatRigourSkipsTheIntervalProofAndSaysSo) {
  ar::ConReachSettings s = coupled_settings();
  s.steps = 5;
  s.horizon = 0.5;
  s.rigour = ar::Rigour::floating;
  const ar::ReachResult fl = ar::run_conreach(pd_loop(), pd_set(), s);
  s.rigour = ar::Rigour::rigorous;
  const ar::ReachResult rg = ar::run_conreach(pd_loop(), pd_set(), s);
  for (std::size_t i = 0; i < fl.steps.size(); ++i) {
    EXPECT_FALSE(fl.steps[i].proved_rigorously);
    EXPECT_TRUE(rg.steps[i].proved_rigorously);
  }
  EXPECT_NEAR(fl.steps.back().r, rg.steps.back().r, 1e-6 * rg.steps.back().r);
}

TEST(ReachCoupledMetric, RigorousModeStopsAStepThatCannotBeProvedWithItsReason) {
  // P_0 with an eigenvalue 1e-14 hidden by a rotation: no metric below it can be certified
  // (P ⪯ P_0 is lost in rounding), so in rigorous mode the analysis stops at the first step,
  // naming the step and the reason (the verdict is then cannot_prove, exit 4), instead of passing.
  const ar::LinearOmegaLoop loop(ar::Vec3(-2, -1, -3).asDiagonal());
  ar::InitialSet init{ar::Mat3::Identity(), 0.1, ar::Vec3(0.65, 0.54, 0.61), 0.1};
  const ar::Mat3 V = exp(ar::Vec3(0.3, -0.5, 0.7));
  init.P0 = V * ar::Vec3(1.0, 1.0, 1e-14).asDiagonal() * V.transpose();
  ar::ConReachSettings s;
  s.horizon = 0.2;
  s.steps = 2;
  s.rigour = ar::Rigour::rigorous;
  const ar::ReachResult res = ar::run_conreach(loop, init, s);
  EXPECT_FALSE(res.complete);
  EXPECT_TRUE(res.steps.empty());
  EXPECT_EQ(res.stop_time, 0.0);
  const std::string& m = res.stop_reason;
  EXPECT_NE(m.find("step 0 on [0, 0.1] s cannot be proved"), std::string::npos) << m;
  EXPECT_NE(m.find("fallback Q = P = s I at the identity-metric rate: "), std::string::npos) << m;
  const ar::SafetyVerdict v = ar::verify_safety({}, {res});
  EXPECT_FALSE(v.proved);
  EXPECT_FALSE(v.complete);
}
