// The dense HKM / Mehrotra SDP solver (issue 48; docs/reach.md, "Dense SDP solver"): against
// CSDP on random feasible instances, a closed-form problem, infeasible problems, solve_sdp's
// fallback and counts, and ConReach's paper example.
//
// ATTIGUARD_DENSE_SDP_INSTANCES=N runs N random instances instead of 200 (the 10⁴ measurement of
// docs/performance.md).

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <random>
#include <string>

#include "attiguard/reach/conreach.hpp"
#include "attiguard/reach/contraction_sdp.hpp"
#include "attiguard/reach/dense_sdp.hpp"
#include "attiguard/reach/sdp_solver.hpp"

namespace ar = attiguard::reach;

namespace dense_sdp_test {

/// solve_sdp's dense path on (DenseFirst) or off (CsdpOnly, as before issue 48) while in scope.
template <bool On>
class DenseSwitch {
 public:
  DenseSwitch() : was_(ar::dense_sdp_enabled()) { ar::set_dense_sdp_enabled(On); }
  ~DenseSwitch() { ar::set_dense_sdp_enabled(was_); }
  DenseSwitch(const DenseSwitch&) = delete;
  DenseSwitch& operator=(const DenseSwitch&) = delete;

 private:
  bool was_;
};
using CsdpOnly = DenseSwitch<false>;
using DenseFirst = DenseSwitch<true>;

Eigen::MatrixXd random_symmetric(std::mt19937_64& rng, int s) {
  std::normal_distribution<double> g(0.0, 1.0);
  Eigen::MatrixXd A(s, s);
  for (int i = 0; i < s; ++i) {
    for (int j = 0; j <= i; ++j) A(i, j) = A(j, i) = g(rng);
  }
  return A;
}

Eigen::MatrixXd random_pd(std::mt19937_64& rng, int s) {
  const Eigen::MatrixXd B = random_symmetric(rng, s);
  return B * B.transpose() / s + 0.1 * Eigen::MatrixXd::Identity(s, s);
}

/// One term: dense (Gaussian) or, a third of the time, a basis matrix e_a e_bᵀ + e_b e_aᵀ as the
/// metric bounds of contraction_sdp.cpp use.
Eigen::MatrixXd random_term(std::mt19937_64& rng, int s) {
  if (std::uniform_int_distribution<int>(0, 2)(rng) == 0) {
    std::uniform_int_distribution<int> idx(0, s - 1);
    const int a = idx(rng);
    const int b = idx(rng);
    Eigen::MatrixXd E = Eigen::MatrixXd::Zero(s, s);
    E(a, b) = E(b, a) = 1.0;
    return E;
  }
  return random_symmetric(rng, s);
}

/// Feasible and bounded by construction: F0 = S0 − Σ y0_i F_i with S0 ≻ 0 (a strictly feasible
/// y0) and b_i = Σ_k ⟨F_ik, Z0_k⟩ with Z0 ≻ 0 (a strictly feasible primal point).
ar::LmiProblem random_instance(std::mt19937_64& rng) {
  const int m = std::uniform_int_distribution<int>(12, 30)(rng);
  const int sizes[] = {1, 3, 3, 4, 5, 6, 6, 9};
  std::uniform_int_distribution<int> pick(0, 7);
  std::bernoulli_distribution uses(0.6);
  std::normal_distribution<double> g(0.0, 1.0);
  ar::LmiProblem p(m);
  int svec = 0;
  std::vector<bool> used(static_cast<std::size_t>(m), false);
  Eigen::VectorXd y0(m);
  for (int i = 0; i < m; ++i) y0(i) = g(rng);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(m);
  auto all_used = [&] { return std::all_of(used.begin(), used.end(), [](bool u) { return u; }); };
  for (int k = 0; !all_used() || k < 2; ++k) {
    const int s = sizes[pick(rng)];
    svec += s * (s + 1) / 2;
    const int blk = p.add_block(s);
    Eigen::MatrixXd F0 = random_pd(rng, s);
    const Eigen::MatrixXd Z0 = random_pd(rng, s);
    // Variables still unused go into a block of size ≥ 3 once the blocks have room for twice the
    // variables (so that the F_i are linearly independent, as ConReach's are).
    const bool last = svec >= 2 * m && k >= 1 && s >= 3;
    for (int i = 0; i < m; ++i) {
      if (!(uses(rng) || (last && !used[static_cast<std::size_t>(i)]))) continue;
      Eigen::MatrixXd F = random_term(rng, s);
      if (s == 1) F(0, 0) = g(rng);
      used[static_cast<std::size_t>(i)] = true;
      p.add_term(blk, i, F);
      F0 -= y0(i) * F;
      b(i) += F.cwiseProduct(Z0).sum();
    }
    p.add_constant(blk, F0);
  }
  for (int i = 0; i < m; ++i) p.set_objective(i, b(i));
  return p;
}

/// Whether the F_i of the problem are linearly independent (Gram matrix well conditioned), as
/// ConReach's are; dependent ones are left to CSDP (dense_sdp.hpp).
bool independent(const ar::LmiProblem& p) {
  const int m = p.num_variables();
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(m, m);
  for (const ar::LmiBlock& blk : p.blocks()) {
    for (const auto& [i, Fi] : blk.terms) {
      for (const auto& [j, Fj] : blk.terms) G(i, j) += Fi.cwiseProduct(Fj).sum();
    }
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(G, Eigen::EigenvaluesOnly);
  return es.eigenvalues()(0) > 1e-6 * es.eigenvalues()(m - 1);
}

/// A random instance with linearly independent F_i.
ar::LmiProblem random_independent_instance(std::mt19937_64& rng) {
  for (;;) {
    ar::LmiProblem p = random_instance(rng);
    if (independent(p)) return p;
  }
}

int instance_count() {
  const char* env = std::getenv("ATTIGUARD_DENSE_SDP_INSTANCES");
  return env != nullptr ? std::max(1, std::atoi(env)) : 200;
}

}  // namespace dense_sdp_test

TEST(DenseSdp, AgreesWithCsdpOnRandomFeasibleInstances) {
  std::mt19937_64 rng(20261207);
  const int count = dense_sdp_test::instance_count();
  double worst = 0.0;
  int solved = 0;
  int within = 0;  // |dense − CSDP| ≤ 1e-7 max(1, |CSDP|) outright
  long iterations = 0;
  int max_iterations = 0;
  for (int n = 0; n < count; ++n) {
    const ar::LmiProblem p = dense_sdp_test::random_independent_instance(rng);
    ar::DenseSdpSolver solver(p);
    const ar::SdpResult d = solver.solve();
    ar::SdpResult c;
    {
      const dense_sdp_test::CsdpOnly csdp_only;
      c = ar::solve_sdp(p, {}, 1e-6);  // CSDP's y is feasible to about 1e-8, not 1e-9
    }
    ASSERT_EQ(c.status, ar::SdpStatus::solved) << "instance " << n << ": " << c.message;
    if (d.status != ar::SdpStatus::solved) {  // solve_sdp falls back to CSDP (6 of 10⁴)
      std::cout << "instance " << n << " not solved dense: " << d.message << "\n";
      continue;
    }
    ++solved;
    iterations += solver.info().iterations;
    max_iterations = std::max(max_iterations, solver.info().iterations);
    const double rel = std::abs(d.objective - c.objective) / std::max(1.0, std::abs(c.objective));
    worst = std::max(worst, rel);
    within += rel <= 1e-7 ? 1 : 0;
    // CSDP's y violates the LMIs by up to ~1e-8 (ε = −λ_min), which lets its objective lie up to
    // ε tr X* below the optimum (DenseSdpInfo::primal_trace); the dense y is feasible.
    const double csdp_slack = std::max(0.0, -c.min_eigenvalue) * solver.info().primal_trace;
    EXPECT_LE(std::abs(d.objective - c.objective),
              1e-7 * std::max(1.0, std::abs(c.objective)) + csdp_slack)
        << "instance " << n << ": dense " << d.objective << ", CSDP " << c.objective;
    EXPECT_GE(d.objective, c.objective - 1e-7 * std::max(1.0, std::abs(c.objective)));
    EXPECT_GE(d.min_eigenvalue, -1e-9);
  }
  EXPECT_GE(solved, count - std::max(1, count / 100)) << "more than 1 % fell back to CSDP";
  std::cout << "dense SDP vs CSDP: " << count << " instances, " << solved
            << " solved dense, " << within << " within 1e-7 of CSDP outright, worst "
            << "|dense - CSDP| / max(1, |CSDP|) = " << worst
            << ", iterations mean " << static_cast<double>(iterations) / std::max(1, solved)
            << " max " << max_iterations << "\n";
}

TEST(DenseSdp, LargestEigenvalueInClosedForm) {
  // min t s.t. t I − A ⪰ 0: t* = λ_max(A).
  std::mt19937_64 rng(48);
  for (int s : {1, 3, 6, 9}) {
    const Eigen::MatrixXd A = dense_sdp_test::random_symmetric(rng, s);
    ar::LmiProblem p(1);
    const int blk = p.add_block(s);
    p.add_constant(blk, -A);
    p.add_term(blk, 0, Eigen::MatrixXd::Identity(s, s));
    p.set_objective(0, 1.0);
    const ar::SdpResult r = ar::solve_sdp_dense(p);
    ASSERT_EQ(r.status, ar::SdpStatus::solved) << r.message;
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(A);
    EXPECT_NEAR(r.objective, es.eigenvalues()(s - 1), 1e-8 * (1.0 + std::abs(r.objective)));
    EXPECT_GE(r.min_eigenvalue, -1e-9);
  }
}

TEST(DenseSdp, InfeasibleProblemsAreReportedAsSuchByBothSolvers) {
  // y ≥ 1 and y ≤ −1; and y diag(1, −1, 0) − I ⪰ 0.
  ar::LmiProblem p(1);
  const int a = p.add_block(1);
  p.add_constant(a, Eigen::MatrixXd::Constant(1, 1, -1.0));
  p.add_term(a, 0, Eigen::MatrixXd::Constant(1, 1, 1.0));
  const int b = p.add_block(1);
  p.add_constant(b, Eigen::MatrixXd::Constant(1, 1, -1.0));
  p.add_term(b, 0, Eigen::MatrixXd::Constant(1, 1, -1.0));
  p.set_objective(0, 1.0);
  ar::LmiProblem q(1);
  const int c = q.add_block(3);
  q.add_constant(c, -Eigen::MatrixXd::Identity(3, 3));
  q.add_term(c, 0, Eigen::Vector3d(1.0, -1.0, 0.0).asDiagonal().toDenseMatrix());
  q.set_objective(0, 1.0);
  ar::SdpSettings csdp_only;
  csdp_only.solver = ar::SdpSolverKind::csdp;
  for (const ar::LmiProblem* prob : {&p, &q}) {
    // The dense solver ends with an X ⪰ 0 bounding ‖y‖ over the feasible set from below by
    // ≥ 1e4 max{1, ‖y‖}: infeasible, and solve_sdp does not call CSDP (docs/reach.md).
    ar::DenseSdpSolver solver(*prob);
    const ar::SdpResult d = solver.solve();
    EXPECT_EQ(d.status, ar::SdpStatus::infeasible) << d.message;
    EXPECT_TRUE(solver.info().infeasible);
    EXPECT_GE(solver.info().feasible_y_norm_bound, 1e4);
    EXPECT_NE(d.message.find("infeasible"), std::string::npos) << d.message;
    const ar::DenseSdpCounts before = ar::dense_sdp_counts();
    const ar::SdpResult r = ar::solve_sdp(*prob);
    EXPECT_EQ(r.status, ar::SdpStatus::infeasible) << r.message;
    EXPECT_EQ(r.csdp_code, -1);
    const ar::DenseSdpCounts after = ar::dense_sdp_counts();
    EXPECT_EQ(after.infeasible, before.infeasible + 1);
    EXPECT_EQ(after.fallback, before.fallback);
    EXPECT_EQ(after.csdp, before.csdp);
    // CSDP, the reference, agrees.
    EXPECT_EQ(ar::solve_sdp(*prob, csdp_only).status, ar::SdpStatus::infeasible);
  }
}

TEST(DenseSdp, SolveSdpUsesTheDenseSolverAndCountsIt) {
  // max t s.t. [[1, t], [t, 1]] ⪰ 0 and 2 − t ≥ 0: t* = 1.
  ar::LmiProblem p(1);
  const int b = p.add_block(2);
  p.add_constant(b, Eigen::Matrix2d::Identity());
  Eigen::Matrix2d F;
  F << 0, 1, 1, 0;
  p.add_term(b, 0, F);
  const int c = p.add_block(1);
  p.add_constant(c, Eigen::MatrixXd::Constant(1, 1, 2.0));
  p.add_term(c, 0, Eigen::MatrixXd::Constant(1, 1, -1.0));
  p.set_objective(0, -1.0);
  EXPECT_FALSE(ar::dense_sdp_enabled());  // the override is off by default: settings decide
  const dense_sdp_test::DenseFirst dense_first;
  const ar::DenseSdpCounts before = ar::dense_sdp_counts();
  const ar::SdpResult r = ar::solve_sdp(p);
  ASSERT_EQ(r.status, ar::SdpStatus::solved) << r.message;
  EXPECT_EQ(r.csdp_code, -1);  // CSDP not called
  EXPECT_NEAR(r.y(0), 1.0, 1e-8);
  EXPECT_EQ(ar::dense_sdp_counts().dense, before.dense + 1);
  ar::set_dense_sdp_enabled(false);
  ar::SdpSettings csdp_only;
  csdp_only.solver = ar::SdpSolverKind::csdp;
  const ar::SdpResult rc = ar::solve_sdp(p, csdp_only);
  ASSERT_EQ(rc.status, ar::SdpStatus::solved);
  EXPECT_EQ(rc.csdp_code, 0);
  EXPECT_EQ(ar::dense_sdp_counts().dense, before.dense + 1);
  // The default settings choose the dense solver (SdpSolverKind::dense, issue 48).
  const ar::SdpResult rd = ar::solve_sdp(p);
  ASSERT_EQ(rd.status, ar::SdpStatus::solved);
  EXPECT_EQ(rd.csdp_code, -1);
  EXPECT_EQ(ar::dense_sdp_counts().dense, before.dense + 2);
}

TEST(DenseSdp, PaperStepZeroMetricAgreesWithCsdp) {
  const ar::LinearOmegaLoop loop(ar::Vec3(-2, -1, -3).asDiagonal());
  const ar::Box3 U0{ar::Vec3(0.442, 0.398, 0.361), ar::Vec3(0.750, 0.640, 0.710)};
  const ar::LmiEnclosure enc = loop.lmi_enclosure({}, U0);
  const dense_sdp_test::DenseFirst dense_first;
  auto solve = [&] {
    return ar::solve_metric(enc, ar::Mat3::Identity(), ar::Mat3::Identity(), 0.1871,
                            ar::MetricObjective::max_trace_q, {});
  };
  const ar::MetricSolution d = solve();
  ar::MetricSolution c;
  {
    const dense_sdp_test::CsdpOnly csdp_only;
    c = solve();
  }
  ASSERT_TRUE(d.ok) << d.message;
  ASSERT_TRUE(c.ok) << c.message;
  EXPECT_NE(d.message.find("dense"), std::string::npos) << d.message;
  EXPECT_NEAR(d.Q.trace(), c.Q.trace(), 1e-7 * (1.0 + std::abs(c.Q.trace())));
}

TEST(DenseSdp, PaperExampleSolvesItsSdpsDense) {
  const ar::LinearOmegaLoop loop(ar::Vec3(-2, -1, -3).asDiagonal());
  const ar::InitialSet set{ar::Mat3::Identity(), 0.1, ar::Vec3(0.65, 0.54, 0.61), 0.1};
  const dense_sdp_test::DenseFirst dense_first;
  const ar::DenseSdpCounts before = ar::dense_sdp_counts();
  const ar::ReachResult res = ar::run_conreach(loop, set, {});
  const ar::DenseSdpCounts after = ar::dense_sdp_counts();
  const long dense = after.dense - before.dense;
  const long fallback = after.fallback - before.fallback;
  std::cout << "paper example: " << dense << " SDPs dense, " << fallback << " fell back to CSDP\n";
  EXPECT_FALSE(res.steps.empty());
  EXPECT_GT(dense, 0);
}

TEST(DenseSdp, WarmStartFromANeighbouringSdpReachesTheColdOptimumInFewerIterations) {
  // The paper's step-0 SDP, then the same SDP at other rates and over a smaller enclosure (the
  // line search's and the next step's problems): reloaded into the solver of the first one and
  // started from its solution, the dense solver reaches the cold start's optimum in fewer
  // iterations (docs/reach.md, "Dense SDP solver").
  const ar::LinearOmegaLoop loop(ar::Vec3(-2, -1, -3).asDiagonal());
  const ar::Box3 U0{ar::Vec3(0.442, 0.398, 0.361), ar::Vec3(0.750, 0.640, 0.710)};
  const ar::Box3 U1{ar::Vec3(0.40, 0.36, 0.33), ar::Vec3(0.70, 0.60, 0.66)};
  const ar::StateMetric prev{ar::Mat3::Identity(), ar::Mat3::Zero(), ar::Mat3::Identity()};
  const ar::LmiProblem first = ar::metric_problem(loop.lmi_enclosure({}, U0), prev, 0.1871,
                                                  ar::MetricObjective::max_trace_q, {});
  int cold_total = 0;
  int warm_total = 0;
  for (const ar::Box3& U : {U0, U1}) {
    for (double c : {0.1871, 0.19, 0.21}) {
      const ar::LmiProblem p =
          ar::metric_problem(loop.lmi_enclosure({}, U), prev, c, ar::MetricObjective::max_trace_q, {});
      ar::DenseSdpSolver warm(first);
      ASSERT_EQ(warm.solve().status, ar::SdpStatus::solved);
      ASSERT_TRUE(warm.reload(p));
      ar::DenseSdpSolver cold(p);
      const ar::SdpResult rc = cold.solve();
      const ar::SdpResult rw = warm.solve_warm(ar::kDenseSdpWarmShift);
      ASSERT_EQ(rc.status, ar::SdpStatus::solved) << rc.message;
      ASSERT_EQ(rw.status, ar::SdpStatus::solved) << rw.message;
      EXPECT_NEAR(rw.objective, rc.objective, 1e-8 * (1.0 + std::abs(rc.objective))) << c;
      EXPECT_GE(rw.min_eigenvalue, -1e-9);
      cold_total += cold.info().iterations;
      warm_total += warm.info().iterations;
    }
  }
  std::cout << "warm start: " << warm_total << " iterations for 6 SDPs, cold " << cold_total << "\n";
  EXPECT_LT(warm_total, cold_total);
}

TEST(DenseSdp, AWorkspaceKeepsOneSolverPerShapeAndReloadRefusesAnotherShape) {
  std::mt19937_64 rng(7);
  auto max_eigenvalue_problem = [&](int s) {  // min t s.t. t I − A ⪰ 0
    ar::LmiProblem p(1);
    const int blk = p.add_block(s);
    p.add_constant(blk, -dense_sdp_test::random_symmetric(rng, s));
    p.add_term(blk, 0, Eigen::MatrixXd::Identity(s, s));
    p.set_objective(0, 1.0);
    return p;
  };
  const ar::LmiProblem p4 = max_eigenvalue_problem(4);
  const ar::LmiProblem p4b = max_eigenvalue_problem(4);
  const ar::LmiProblem p3 = max_eigenvalue_problem(3);
  ar::DenseSdpSolver solver(p4);
  EXPECT_FALSE(solver.reload(p3));
  EXPECT_EQ(solver.solve_warm(ar::kDenseSdpWarmShift).objective,
            ar::solve_sdp_dense(p4).objective);  // no solution yet: the same cold solve, same bits

  const dense_sdp_test::DenseFirst dense_first;
  ar::DenseSdpWorkspace ws;
  ar::SdpSettings settings;
  settings.warm_start = &ws;
  for (const ar::LmiProblem* p : {&p4, &p4b, &p3}) {
    const ar::SdpResult via = ar::solve_sdp(*p, settings);
    ASSERT_EQ(via.status, ar::SdpStatus::solved) << via.message;
    EXPECT_NEAR(via.objective, ar::solve_sdp_dense(*p).objective, 1e-8 * (1.0 + std::abs(via.objective)));
    ASSERT_TRUE(ws.solver.has_value());
    EXPECT_TRUE(ws.solver->reload(*p));  // the workspace now holds a solver of p's shape
  }
}
