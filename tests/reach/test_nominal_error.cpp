// The bound on the nominal's integration error (reach/nominal_error.hpp) and the polynomial form
// of the closed loops it differentiates (reach/polynomial_field.hpp).

#include <gtest/gtest.h>

#include <unsupported/Eigen/MatrixFunctions>

#include "attiguard/reach/closed_loop.hpp"
#include "attiguard/reach/conreach.hpp"
#include "attiguard/reach/nominal_error.hpp"
#include "test_support.hpp"

namespace ar = attiguard::reach;
using attiguard::test::random_rotation;
using attiguard::test::random_vector_in_ball;

namespace {
ar::Mat3 random_inertia() {
  const ar::Mat3 Rb = random_rotation();
  const ar::Vec3 d = ar::Vec3(1.0, 1.5, 2.0) + random_vector_in_ball(0.4).cwiseAbs();
  return Rb * d.asDiagonal() * Rb.transpose();
}

/// The loop's state at s+h from (R0, ω0), with RKMK4 step `step` (the nominal's integrator).
std::pair<ar::Mat3, ar::Vec3> rkmk4(const ar::ClosedLoop& loop, const ar::Mat3& R0, const ar::Vec3& w0,
                                    double h, double step) {
  std::pair<ar::Mat3, ar::Vec3> out;
  ar::simulate(loop, R0, w0, {0.0, h}, step, [&](std::size_t k, const ar::Mat3& R, const ar::Vec3& w) {
    if (k == 1) out = {R, w};
  });
  return out;
}

/// The hull of a fine reference trajectory over [0, h] (1000 points), widened by 10 % of its
/// extent plus 1e-3: an enclosure of the solution with a wide margin, as the tube's is.
std::pair<ar::Box3, double> sampled_enclosure(const ar::ClosedLoop& loop, const ar::Mat3& R0,
                                              const ar::Vec3& w0, double h) {
  std::vector<double> times;
  for (int j = 0; j <= 1000; ++j) times.push_back(h * j / 1000.0);
  ar::Box3 box{w0, w0};
  double rho = 0.0;
  ar::simulate(loop, R0, w0, times, 1e-4, [&](std::size_t, const ar::Mat3& R, const ar::Vec3& w) {
    box = box.hull({w, w});
    rho = std::max(rho, attiguard::lie::distance(R0, R));
  });
  return {box.inflated(0.1 * box.radius() + ar::Vec3::Constant(1e-3)), 1.1 * rho + 1e-3};
}
}  // namespace

TEST(ReachPolynomialField, EqualsOmegaDotOfEveryLoop) {
  for (int trial = 0; trial < 20; ++trial) {
    const ar::Mat3 J = random_inertia();
    const ar::LinearOmegaLoop lin(random_rotation() * 3.0);
    const ar::RigidBodyLoop rb(J, random_vector_in_ball(2.0));
    const ar::PdLoop pd(J, 1.7, 2.3, random_rotation());
    for (const ar::ClosedLoop* loop : {static_cast<const ar::ClosedLoop*>(&lin),
                                       static_cast<const ar::ClosedLoop*>(&rb),
                                       static_cast<const ar::ClosedLoop*>(&pd)}) {
      const ar::Mat3 R = random_rotation();
      const ar::Vec3 w = random_vector_in_ball(3.0);
      const ar::Vec3 a = loop->omega_dot(R, w);
      const ar::Vec3 b = loop->polynomial_field().evaluate(R, w);
      EXPECT_LT((a - b).norm(), 1e-12 * (1.0 + a.norm())) << loop->name();
    }
  }
}

// Torque-free asymmetric body at up to 2 rad/s: a coarse RKMK4 nominal (step 0.05 s over a 0.1 s
// sub-step) has errors of 1e-9..1e-7, against a reference with step 1e-4 s (error ~1e-16). The bound must
// contain the error and be tight (within a factor 10 plus the rounding level).
TEST(ReachNominalError, BoundsTheErrorOfACoarseNominalOfAnAsymmetricBody) {
  const ar::RigidBodyLoop loop(ar::Vec3(1.0, 2.0, 3.0).asDiagonal(), ar::Vec3::Zero());
  for (int trial = 0; trial < 10; ++trial) {
    const ar::Mat3 R0 = random_rotation();
    const ar::Vec3 w0 = random_vector_in_ball(2.0);
    const double h = 0.1;
    const auto [R1, w1] = rkmk4(loop, R0, w0, h, 0.05);
    const auto [R_ref, w_ref] = rkmk4(loop, R0, w0, h, 1e-4);
    const auto [box, rho] = sampled_enclosure(loop, R0, w0, h);
    std::string why;
    const auto e = ar::nominal_step_error(loop.polynomial_field(), R0, w0, R1, w1, h, box, rho, why);
    ASSERT_TRUE(e.has_value()) << why;
    const double true_R = attiguard::lie::distance(R_ref, R1);
    EXPECT_GE(e->bound.e_R, true_R - 1e-14);
    EXPECT_LE(e->bound.e_R, 10.0 * true_R + 1e-12);
    for (int k = 0; k < 3; ++k) {
      const double err = std::abs(w_ref(k) - w1(k));
      EXPECT_GE(e->bound.d_omega_b(k), err - 1e-14) << k;
      EXPECT_LE(e->bound.d_omega_b(k), 10.0 * err + 1e-12) << k;
    }
    EXPECT_GE(e->bound.e_omega_b, (w_ref - w1).norm() - 1e-14);
  }
}

// Closed form ω(t) = e^{Mt}ω0 for a general linear ω-dynamics, nominal with a coarse step.
TEST(ReachNominalError, BoundsTheOmegaErrorOfLinearDynamicsComponentwise) {
  for (int trial = 0; trial < 20; ++trial) {
    const ar::Mat3 M = 2.0 * (random_rotation() - ar::Mat3::Identity() * 0.5);
    const ar::LinearOmegaLoop loop(M);
    const ar::Vec3 w0 = random_vector_in_ball(1.0);
    const double h = 0.2;
    const auto [R1, w1] = rkmk4(loop, ar::Mat3::Identity(), w0, h, 0.1);
    const ar::Vec3 w_exact = (M * h).exp() * w0;
    const ar::Box3 box = ar::Box3::around(w0, ar::Vec3::Constant(2.0 * w0.norm() + 1e-3));
    std::string why;
    const auto e = ar::nominal_step_error(loop.polynomial_field(), ar::Mat3::Identity(), w0, R1, w1, h,
                                          box, h * 3.0 * (w0.norm() + 1e-3), why);
    ASSERT_TRUE(e.has_value()) << why;
    for (int k = 0; k < 3; ++k) {
      const double err = std::abs(w_exact(k) - w1(k));
      EXPECT_GE(e->bound.d_omega_b(k), err) << k;
      EXPECT_LE(e->bound.d_omega_b(k), 10.0 * err + 1e-13) << k;
    }
    EXPECT_GE(e->bound.e_omega_b, (w_exact - w1).norm());
  }
}

// A sub-step far too long for the dynamics (|M| h = 2000): no finite bound, with the reason.
TEST(ReachNominalError, RefusesWhenTheRemainderCannotBeBounded) {
  const ar::LinearOmegaLoop loop(ar::Vec3(1000.0, -1.0, -1.0).asDiagonal());
  const ar::Vec3 w0(1.0, 0.0, 0.0);
  const ar::Box3 box{ar::Vec3(-1e300, -1.0, -1.0), ar::Vec3(1e300, 1.0, 1.0)};
  std::string why;
  const auto e = ar::nominal_step_error(loop.polynomial_field(), ar::Mat3::Identity(), w0,
                                        ar::Mat3::Identity(), w0, 2.0, box, 3.0, why);
  EXPECT_FALSE(e.has_value());
  EXPECT_FALSE(why.empty());
}

// Issue 15: removing the nominal's error bound makes a crafted example fail. A single initial
// state (zero deviation) of a torque-free asymmetric body at ~2 rad/s, with a coarse RKMK4
// nominal (step 0.05 s, sub-steps of 0.1 s over 1 s): with ε the tube's end deviation contains
// the exact state (reference step 1e-4 s); with ε omitted it is the rounding allowance only and
// the exact state lies outside it.
TEST(ReachNominalError, TubeWithoutTheNominalErrorBoundMissesTheExactSolution) {
  const ar::RigidBodyLoop loop(ar::Vec3(1.0, 2.0, 3.0).asDiagonal(), ar::Vec3::Zero());
  const ar::Mat3 R0 = ar::Mat3::Identity();
  const ar::Vec3 w0(0.3, 2.0, 0.4);
  std::vector<ar::NominalPoint> nominal;
  std::vector<double> times;
  for (int j = 0; j <= 10; ++j) times.push_back(0.1 * j);
  ar::simulate(loop, R0, w0, times, 0.05, [&](std::size_t k, const ar::Mat3& R, const ar::Vec3& w) {
    nominal.push_back({times[k], R, w});
  });
  ASSERT_EQ(nominal.size(), times.size());
  const auto [R_ref, w_ref] = rkmk4(loop, R0, w0, 1.0, 1e-4);
  const double err_R = attiguard::lie::distance(R_ref, nominal.back().R);
  const double err_w = (w_ref - nominal.back().omega).norm();
  ASSERT_GT(err_w, 1e-9);  // the crafted nominal is coarse enough to matter

  const ar::Deviation start{};
  const ar::TubeResult with = ar::propagate_tube(loop, nominal, start);
  EXPECT_GE(with.end.e_omega_b, err_w);
  EXPECT_GE(with.end.e_R, err_R);
  for (int k = 0; k < 3; ++k) EXPECT_GE(with.end.d_omega_b(k), std::abs(w_ref(k) - nominal.back().omega(k))) << k;

  const ar::TubeResult without =
      ar::propagate_tube(loop, nominal, start, ar::NominalErrorTerm::omitted_unsound);
  EXPECT_LT(without.end.e_omega_b, err_w) << "without the bound the tube still contains the exact state";
}
