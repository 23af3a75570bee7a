// Metrics, d_Q bounds, geodesics (21)/(24), exp atlas (26), boundary representation, partition.

#include <gtest/gtest.h>

#include <cmath>

#include "attiguard/core/errors.hpp"
#include "attiguard/lie/jacobians.hpp"
#include "attiguard/reach/boundary.hpp"
#include "attiguard/reach/geodesic.hpp"
#include "attiguard/reach/metrics.hpp"
#include "attiguard/reach/partition.hpp"
#include "test_support.hpp"

namespace ar = attiguard::reach;
using attiguard::test::random_rotation;
using attiguard::test::random_vector_in_ball;

namespace {
ar::Mat3 random_spd() {
  const ar::Mat3 A = ar::Mat3::Random();
  return A * A.transpose() + 0.3 * ar::Mat3::Identity();
}
}  // namespace

TEST(ReachMetrics, DistanceBoundsAreOrderedAndExactForIdentity) {
  for (int k = 0; k < 200; ++k) {
    const ar::Mat3 Q = random_spd();
    const ar::Mat3 R1 = random_rotation();
    const ar::Mat3 R2 = R1 * attiguard::lie::exp(random_vector_in_ball(2.5));
    EXPECT_LE(ar::dq_lower(Q, R1, R2), ar::dq_upper(Q, R1, R2) + 1e-12);
    EXPECT_NEAR(ar::dq_upper(ar::Mat3::Identity(), R1, R2), attiguard::lie::distance(R1, R2), 1e-12);
    EXPECT_NEAR(ar::dq_lower(ar::Mat3::Identity(), R1, R2), attiguard::lie::distance(R1, R2), 1e-12);
  }
}

TEST(ReachMetrics, RejectsNonSpdMetrics) {
  ar::Mat3 M = ar::Mat3::Identity();
  M(2, 2) = -0.1;
  EXPECT_THROW(ar::require_spd(M, "Q"), attiguard::InputError);
  M = ar::Mat3::Identity();
  M(0, 1) = 0.3;  // not symmetric
  EXPECT_THROW(ar::require_spd(M, "Q"), attiguard::InputError);
  M = ar::Mat3::Identity();
  M(1, 1) = std::nan("");
  EXPECT_THROW(ar::require_spd(M, "Q"), attiguard::InputError);
  EXPECT_NO_THROW(ar::require_spd(random_spd(), "Q"));
}

TEST(ReachGeodesic, ReducedEquationPreservesQNorm) {
  // wᵀQẇ = −wᵀ(w × Qw) = 0: the speed √(wᵀQw) of a G_Q geodesic is constant.
  for (int k = 0; k < 100; ++k) {
    const ar::Mat3 Q = random_spd();
    const ar::Vec3 w = random_vector_in_ball(2.0);
    EXPECT_NEAR(w.dot(Q * ar::reduced_geodesic_rate(Q, w)), 0.0, 1e-12);
  }
  // For Q = I geodesics are one-parameter subgroups: ẇ = 0.
  EXPECT_LT(ar::reduced_geodesic_rate(ar::Mat3::Identity(), ar::Vec3(0.3, -0.2, 0.9)).norm(), 1e-15);
}

TEST(ReachGeodesic, ExpAtlasFIsTheInverseRightJacobian) {
  for (int k = 0; k < 100; ++k) {
    const ar::Vec3 r = random_vector_in_ball(3.0);
    EXPECT_LT((ar::exp_atlas_f(r) - attiguard::lie::right_jacobian_inverse(r)).norm(), 1e-9);
  }
  EXPECT_LT((ar::exp_atlas_f(ar::Vec3(1e-7, 0, 0)) - ar::Mat3::Identity()).norm(), 1e-6);
}

TEST(ReachGeodesic, ChartDynamics26MatchGeodesicEquation24) {
  for (int k = 0; k < 30; ++k) {
    const ar::Mat3 Q = random_spd();
    const ar::Mat3 R0 = attiguard::lie::exp(random_vector_in_ball(0.8));
    const ar::Vec3 w0 = random_vector_in_ball(0.6);
    const ar::Mat3 R1 = ar::geodesic_endpoint(Q, R0, w0, 200);
    for (int chart = 0; chart < 4; ++chart) {
      const ar::Vec3 r0 = ar::chart_coordinates(chart, R0);
      if (r0.norm() + 0.6 > 3.0) continue;
      const ar::Vec3 r1 = ar::chart_geodesic_endpoint(Q, chart, r0, w0, 200);
      EXPECT_LT(attiguard::lie::distance(ar::chart_inverse(chart, r1), R1), 1e-9) << chart;
    }
  }
}

// A long geodesic of an anisotropic metric: the step count follows ‖w0‖ and κ (geodesic_steps),
// so the default 64 steps give the endpoint of a 20 000-step reference; 64 fixed steps did not.
TEST(ReachGeodesic, LongGeodesicsOfAnisotropicMetricsTakeEnoughSteps) {
  const ar::Mat3 Q = ar::Vec3(1.0, 2.0, 8.0).asDiagonal();
  const ar::Mat3 R0 = attiguard::lie::exp(ar::Vec3(0.3, -0.2, 0.1));
  for (const ar::Vec3& w0 : {ar::Vec3(6.0, 0.5, 0.3), ar::Vec3(0.2, 4.0, 1.5), ar::Vec3(2.0, 2.0, 2.5)}) {
    const ar::Mat3 R_ref = ar::geodesic_endpoint(Q, R0, w0, 20000);
    EXPECT_GT(ar::geodesic_steps(Q, w0), 64.0);
    EXPECT_LT(attiguard::lie::distance(ar::geodesic_endpoint(Q, R0, w0), R_ref), 1e-7) << w0.transpose();
  }
  // Steps beyond kMaxGeodesicSteps: a NumericalError, never a non-finite endpoint.
  const ar::Mat3 Q_bad = ar::Vec3(1.0, 1.0, 1e4).asDiagonal();
  EXPECT_THROW((void)ar::geodesic_endpoint(Q_bad, R0, ar::Vec3(300.0, 0.0, 0.0)), attiguard::NumericalError);
}

// A ball with r/√λ_max(Q) ≥ π is all of SO(3): no boundary rows (the corpus loop 34 ends with a
// ball of radius 3.9e7 whose geodesics overflowed the fixed-step integrator).
TEST(ReachBoundary, ABallCoveringSo3HasNoBoundary) {
  const ar::Mat3 Q = ar::Vec3(0.91, 0.93, 0.94).asDiagonal();
  const ar::Mat3 Rc = attiguard::lie::exp(ar::Vec3(0.5, 0.1, -0.3));
  EXPECT_TRUE(ar::ball_covers_rotations(Q, 3.9e7));
  EXPECT_TRUE(ar::ball_boundary_atlas(Q, 3.9e7, Rc, 50).empty());
  const double r_edge = M_PI * std::sqrt(0.94);
  EXPECT_TRUE(ar::ball_covers_rotations(Q, r_edge * (1 + 1e-12)));
  EXPECT_FALSE(ar::ball_covers_rotations(Q, r_edge * (1 - 1e-12)));
  EXPECT_EQ(ar::ball_boundary_atlas(Q, 0.999 * r_edge, Rc, 50).size(), 50U);
}

TEST(ReachGeodesic, ChartInverseRoundTripAndBestChart) {
  for (int k = 0; k < 100; ++k) {
    const ar::Mat3 R = random_rotation();
    const int c = ar::best_chart(R);
    EXPECT_LT(attiguard::lie::distance(ar::chart_inverse(c, ar::chart_coordinates(c, R)), R), 1e-9);
    // Some chart always has ‖r‖ ≤ 2π/3 (the four charts are centred π apart).
    EXPECT_LE(ar::chart_coordinates(c, R).norm(), 2.0 * M_PI / 3.0 + 1e-9);
  }
}

TEST(ReachBoundary, BoundaryPointsLieOnTheBallWithinTheBounds) {
  const ar::Mat3 Q = (ar::Vec3(0.99, 0.96, 0.99)).asDiagonal();
  const ar::Mat3 Rc = attiguard::lie::exp(ar::Vec3(0.2, -0.1, 0.3));
  const double r = 0.3;
  const auto pts = ar::ball_boundary(Q, r, Rc, 0, 100);
  ASSERT_EQ(pts.size(), 100u);
  for (const ar::Vec3& p : pts) {
    const ar::Mat3 R = ar::chart_inverse(0, p);
    // Endpoint of a geodesic of G_Q-length r: d_Q ≤ r, so the lower bound is ≤ r.
    EXPECT_LE(ar::dq_lower(Q, Rc, R), r + 1e-9);
  }
  // A ball that cannot fit in one chart is an error, not a crash.
  EXPECT_THROW((void)ar::ball_boundary(Q, 3.0, Rc, 0, 10), attiguard::NumericalError);
}

TEST(ReachPartition, CellsCoverTheInitialSet) {
  ar::InitialSet whole{attiguard::lie::exp(ar::Vec3(0.1, 0.2, -0.3)), 0.3, ar::Vec3(0.1, 0.2, 0.3), 0.2};
  const auto cells = ar::partition_initial_set(whole, 3, 2);
  ASSERT_GT(cells.size(), 8u);
  for (int k = 0; k < 3000; ++k) {
    const ar::Mat3 R = whole.R0 * attiguard::lie::exp(random_vector_in_ball(whole.attitude_radius));
    const ar::Vec3 w = whole.omega0 + random_vector_in_ball(whole.omega_radius);
    bool covered = false;
    for (const auto& c : cells) {
      covered = covered || (attiguard::lie::distance(c.R0, R) <= c.attitude_radius &&
                            (w - c.omega0).norm() <= c.omega_radius);
    }
    ASSERT_TRUE(covered);
  }
  EXPECT_THROW((void)ar::partition_initial_set(whole, 0, 1), attiguard::InputError);
}
