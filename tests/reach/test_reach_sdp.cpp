// The CSDP wrapper: results, failures as statuses, no output, no ./param.csdp, threads.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <future>
#include <vector>

#include "attiguard/reach/contraction_sdp.hpp"
#include "attiguard/reach/sdp_solver.hpp"

namespace ar = attiguard::reach;

namespace {
/// max t s.t. [[1, t], [t, 1]] ⪰ 0 and [[2 − t]] ⪰ 0: t* = 1.
ar::LmiProblem simple_problem() {
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
  return p;
}
}  // namespace

TEST(ReachSdp, SolvesASmallProblemSilently) {
  testing::internal::CaptureStdout();
  const ar::SdpResult r = ar::solve_sdp(simple_problem());
  const std::string out = testing::internal::GetCapturedStdout();
  ASSERT_EQ(r.status, ar::SdpStatus::solved) << r.message;
  EXPECT_NEAR(r.y(0), 1.0, 1e-6);
  EXPECT_GE(r.min_eigenvalue, -1e-9);
  EXPECT_EQ(out, "");
}

TEST(ReachSdp, InfeasibleProblemIsAStatusNotACrash) {
  // y ≥ 1 and y ≤ −1.
  ar::LmiProblem p(1);
  const int a = p.add_block(1);
  p.add_constant(a, Eigen::MatrixXd::Constant(1, 1, -1.0));
  p.add_term(a, 0, Eigen::MatrixXd::Constant(1, 1, 1.0));
  const int b = p.add_block(1);
  p.add_constant(b, Eigen::MatrixXd::Constant(1, 1, -1.0));
  p.add_term(b, 0, Eigen::MatrixXd::Constant(1, 1, -1.0));
  p.set_objective(0, 1.0);
  testing::internal::CaptureStdout();
  const ar::SdpResult r = ar::solve_sdp(p);
  EXPECT_EQ(testing::internal::GetCapturedStdout(), "");
  EXPECT_NE(r.status, ar::SdpStatus::solved);
  EXPECT_FALSE(r.message.empty());
}

TEST(ReachSdp, RejectsNaNAndMalformedDataBeforeCallingCsdp) {
  ar::LmiProblem p = simple_problem();
  p.add_constant(0, Eigen::Matrix2d::Constant(std::nan("")));
  EXPECT_THROW((void)ar::solve_sdp(p), std::invalid_argument);
  ar::LmiProblem q(2);  // variable 1 appears nowhere
  const int b = q.add_block(1);
  q.add_term(b, 0, Eigen::MatrixXd::Constant(1, 1, 1.0));
  EXPECT_THROW((void)ar::solve_sdp(q), std::invalid_argument);
  ar::LmiProblem s(1);
  const int c = s.add_block(2);
  Eigen::Matrix2d F;
  F << 0, 1, 0, 0;  // not symmetric
  s.add_term(c, 0, F);
  EXPECT_THROW((void)ar::solve_sdp(s), std::invalid_argument);
}

TEST(ReachSdp, IgnoresParamCsdpInTheWorkingDirectory) {
  // CSDP's own initparams() would read this file (maxiter=1, printlevel=3).
  const auto dir = std::filesystem::temp_directory_path() / "attiguard_param_csdp_test";
  std::filesystem::create_directories(dir);
  { std::ofstream(dir / "param.csdp") << "axtol=1.0e-1\nmaxiter=1\nprintlevel=3\n"; }
  const auto cwd = std::filesystem::current_path();
  std::filesystem::current_path(dir);
  testing::internal::CaptureStdout();
  const ar::SdpResult r = ar::solve_sdp(simple_problem());
  const std::string out = testing::internal::GetCapturedStdout();
  std::filesystem::current_path(cwd);
  std::filesystem::remove_all(dir);
  ASSERT_EQ(r.status, ar::SdpStatus::solved);
  EXPECT_NEAR(r.y(0), 1.0, 1e-6);
  EXPECT_EQ(out, "");
}

TEST(ReachSdp, ConcurrentCallsAreSerialisedAndAgree) {
  std::vector<std::future<ar::SdpResult>> fs;
  for (int i = 0; i < 8; ++i) {
    fs.push_back(std::async(std::launch::async, [] { return ar::solve_sdp(simple_problem()); }));
  }
  for (auto& f : fs) {
    const ar::SdpResult r = f.get();
    ASSERT_EQ(r.status, ar::SdpStatus::solved);
    EXPECT_NEAR(r.y(0), 1.0, 1e-6);
  }
}

TEST(ReachSdp, InfeasibleContractionRateFallsOutCleanly) {
  // c far below the identity rate of the paper's example: (20) is infeasible.
  const ar::LinearOmegaLoop loop(ar::Vec3(-2, -1, -3).asDiagonal());
  const ar::Box3 U0{ar::Vec3(0.442, 0.398, 0.361), ar::Vec3(0.750, 0.640, 0.710)};
  const ar::LmiEnclosure enc = loop.lmi_enclosure({}, U0);
  const ar::MetricSolution sol = ar::solve_metric(enc, ar::Mat3::Identity(), ar::Mat3::Identity(),
                                                  -5.0, ar::MetricObjective::max_trace_q, {});
  EXPECT_FALSE(sol.ok);
  // The fallback is always certified.
  const ar::MetricSolution fb = ar::fallback_metric(enc, ar::Mat3::Identity(), ar::Mat3::Identity());
  EXPECT_TRUE(fb.ok);
  EXPECT_LE(fb.worst_eigenvalue, 0.0);
}
