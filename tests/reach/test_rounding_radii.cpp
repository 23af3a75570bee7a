// Rounding sites of the ball radii (reach/proved_radii.hpp, docs/reach.md "Rounding sites"):
// for each, a constructed case where the round-to-nearest value lies below the exact one (so it
// would claim a ball smaller than the truth), and the proved value that does not.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "attiguard/reach/metrics.hpp"
#include "attiguard/reach/proved_radii.hpp"

namespace attiguard::reach {
namespace rounding_radii_test {

using Real = long double;  // 64-bit mantissa: decides a one-ulp (2⁻⁵²) difference of doubles

/// Draws (x, y) until `float_value(x, y) < exact(x, y)` by more than the long double's own error;
/// the search is deterministic (fixed seed) and such draws are frequent (≈ half of them).
template <typename Float, typename Exact>
std::pair<double, double> find_rounded_below(const Float& float_value, const Exact& exact) {
  std::mt19937_64 rng(47);
  std::uniform_real_distribution<double> u(0.1, 10.0);
  for (int k = 0; k < 100000; ++k) {
    const double x = u(rng);
    const double y = u(rng);
    const Real e = exact(x, y);
    if (static_cast<Real>(float_value(x, y)) < e * (1.0L - 1e-18L)) return {x, y};
  }
  ADD_FAILURE() << "no case found";
  return {1.0, 1.0};
}

}  // namespace rounding_radii_test

using rounding_radii_test::find_rounded_below;
using rounding_radii_test::Real;

TEST(RoundingRadii, ProjectionRadiusIsNotBelowTheExactOneWhereRoundToNearestIs) {
  // λ_min(diag(q I, p I))'s attitude block is q exactly: the projection radius is r/√q.
  auto exact = [](double r, double q) { return static_cast<Real>(r) / std::sqrt(static_cast<Real>(q)); };
  auto rn = [](double r, double q) { return attitude_enclosure_radius(q * Mat3::Identity(), r); };
  const auto [r, q] = find_rounded_below(rn, exact);
  ASSERT_LT(static_cast<Real>(rn(r, q)), exact(r, q));  // the round-to-nearest value is too small
  const StateMetric m{q * Mat3::Identity(), Mat3::Zero(), 2.0 * Mat3::Identity()};
  const double proved = proved_projection_radius(m, r, StateBlock::attitude);
  EXPECT_GE(static_cast<Real>(proved), exact(r, q));
  EXPECT_LT(proved, exact(r, q) * (1.0L + 1e-9L));  // and tight
  EXPECT_GE(static_cast<Real>(radius_over_sqrt_up(r, q)), exact(r, q));
}

TEST(RoundingRadii, OmegaHalfWidthsAreNotBelowTheExactOnesWhereRoundToNearestIs) {
  auto exact = [](double r, double p) { return static_cast<Real>(r) / std::sqrt(static_cast<Real>(p)); };
  auto rn = [](double r, double p) { return p_ball_half_widths(p * Mat3::Identity(), r)(0); };
  const auto [r, p] = find_rounded_below(rn, exact);
  ASSERT_LT(static_cast<Real>(rn(r, p)), exact(r, p));
  const StateMetric m{Mat3::Identity(), Mat3::Zero(), p * Mat3::Identity()};
  const Vec3 h = proved_omega_half_widths(m, r);
  for (int k = 0; k < 3; ++k) {
    EXPECT_GE(static_cast<Real>(h(k)), exact(r, p)) << k;
    EXPECT_LT(h(k), exact(r, p) * (1.0L + 1e-9L)) << k;
  }
}

TEST(RoundingRadii, CoverRadiusIsNotBelowTheExactOneWhereRoundToNearestIs) {
  // Product metric diag(q I, I), b = 1: sup zᵀMz over ‖z_R‖ ≤ a, ‖z_ω‖ ≤ 1 is q a² + 1.
  auto exact = [](double q, double a) {
    return std::sqrt(static_cast<Real>(q) * a * a + 1.0L);
  };
  auto rn = [](double q, double a) {
    return metric_cover_radius({q * Mat3::Identity(), Mat3::Zero(), Mat3::Identity()}, a, 1.0);
  };
  const auto [q, a] = find_rounded_below(rn, exact);
  ASSERT_LT(static_cast<Real>(rn(q, a)), exact(q, a));
  const double proved = proved_cover_radius({q * Mat3::Identity(), Mat3::Zero(), Mat3::Identity()}, a, 1.0);
  EXPECT_GE(static_cast<Real>(proved), exact(q, a));
  EXPECT_LT(proved, exact(q, a) * (1.0L + 1e-9L));
}

TEST(RoundingRadii, CoverRadiusOfACoupledMetricCoversSampledPointsOfTheSet) {
  const Mat3 S = (Mat3() << 0.3, 0.1, -0.2, 0.0, 0.25, 0.05, 0.1, -0.1, 0.2).finished();
  const StateMetric m{2.0 * Mat3::Identity(), S, Mat3::Identity()};
  const double a = 0.3;
  const double b = 0.7;
  const double proved = proved_cover_radius(m, a, b);
  EXPECT_LE(proved, metric_cover_radius(m, a, b) * (1.0 + 1e-9));
  std::mt19937_64 rng(3);
  std::normal_distribution<double> g;
  const Mat6 M = metric_matrix(m);
  for (int k = 0; k < 2000; ++k) {
    Eigen::Matrix<double, 6, 1> z;
    for (int j = 0; j < 6; ++j) z(j) = g(rng);
    z.head<3>() *= a / z.head<3>().norm();
    z.tail<3>() *= b / z.tail<3>().norm();
    EXPECT_LE(std::sqrt(z.dot(M * z)), proved);
  }
  EXPECT_EQ(proved_cover_radius(m, 0.0, 0.0), 0.0);
  EXPECT_GE(proved_cover_radius(m, a, 0.0), a * std::sqrt(2.0));  // λ_max(Q) a² exactly
}

TEST(RoundingRadii, BallGrowthIsNotBelowTheExactOneWhereRoundToNearestIs) {
  // r e^{cΔt} + allowance with c = −0.375 and allowance 2⁻⁵⁷ r (both exact in binary).
  auto exact = [](double r, double dt) {
    return static_cast<Real>(r) * std::exp(-0.375L * static_cast<Real>(dt)) + std::ldexp(static_cast<Real>(r), -57);
  };
  auto rn = [](double r, double dt) { return r * std::exp(-0.375 * dt) + std::ldexp(r, -57); };
  const auto [r, dt] = find_rounded_below(rn, exact);
  ASSERT_LT(static_cast<Real>(rn(r, dt)), exact(r, dt));
  const double proved = proved_ball_growth(r, -0.375, dt, std::ldexp(r, -57));
  EXPECT_GE(static_cast<Real>(proved), exact(r, dt));
  EXPECT_LT(proved, exact(r, dt) * (1.0L + 1e-14L));
}

TEST(RoundingRadii, SchurLowerBoundOfACoupledMetricIsBelowItsEigenvalueAndPositive) {
  const Mat3 S = (Mat3() << 0.3, 0.1, -0.2, 0.0, 0.25, 0.05, 0.1, -0.1, 0.2).finished();
  const StateMetric m{2.0 * Mat3::Identity(), S, Mat3::Identity()};
  for (StateBlock block : {StateBlock::attitude, StateBlock::omega}) {
    const double f = lambda_min(block == StateBlock::attitude ? attitude_schur(m) : omega_schur(m));
    const double lo = proved_schur_lower(m, block);
    EXPECT_GT(lo, 0.0);
    EXPECT_LE(lo, f);
    EXPECT_GT(lo, f * (1.0 - 1e-9));
  }
  // An indefinite "metric" proves nothing: radius +∞, not a number that looks like a bound.
  const StateMetric bad{Mat3::Identity(), 2.0 * Mat3::Identity(), Mat3::Identity()};
  EXPECT_EQ(proved_schur_lower(bad, StateBlock::attitude), 0.0);
  EXPECT_TRUE(std::isinf(proved_projection_radius(bad, 1.0, StateBlock::attitude)));
}

}  // namespace attiguard::reach
