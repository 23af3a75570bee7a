// The tube's rounding sites (docs/reach.md, "Rounding sites"; tube.hpp): each site is called on
// floating-point data whose exact result lies just beyond what round-to-nearest computes
// (1 + 2⁻⁵³-style sums, products whose rounding goes down), and its bound is checked against the
// exact value, known by rational reasoning or an error-free transformation (TwoSum, TwoProduct
// via fma). Each test also checks that the round-to-nearest value violates the bound's
// requirement, so the test fails if the site computes in round-to-nearest.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "attiguard/reach/tube.hpp"

namespace ar = attiguard::reach;

namespace rounding_tube_test {

/// a + b = s + e exactly (Knuth's TwoSum).
struct Exact {
  double s;
  double e;
};
Exact two_sum(double a, double b) {
  const double s = a + b;
  const double bp = s - a;
  const double ap = s - bp;
  return {s, (a - ap) + (b - bp)};
}
/// a·b = p + e exactly (fma).
Exact two_prod(double a, double b) {
  const double p = a * b;
  return {p, std::fma(a, b, -p)};
}
/// r ≥ s + e exactly, for |e| ≤ ulp(s)/2.
bool at_least(double r, const Exact& x) { return r > x.s || (r == x.s && x.e <= 0.0); }
/// r ≤ s + e exactly.
bool at_most(double r, const Exact& x) { return r < x.s || (r == x.s && x.e >= 0.0); }

constexpr double tiny27 = 0x1p-27;  // (1, 2⁻²⁷, 0) has norm √(1 + 2⁻⁵⁴) > 1; computed: exactly 1

ar::Box3 point_box(const ar::Vec3& v) { return {v, v}; }

}  // namespace rounding_tube_test

namespace rtt = rounding_tube_test;

TEST(RoundingTube, SubStepDurationContainsTheExactDifference) {
  const double t0 = 0.3;
  const double t1 = 1.7;
  const rtt::Exact d = rtt::two_sum(t1, -t0);
  ASSERT_NE(d.e, 0.0);  // round-to-nearest t1 − t0 misses the exact duration
  const ar::Interval h = ar::sub_step_duration(t0, t1);
  EXPECT_TRUE(rtt::at_most(h.lo, d));
  EXPECT_TRUE(rtt::at_least(h.hi, d));
  // An exact difference (Sterbenz) stays a point.
  const ar::Interval p = ar::sub_step_duration(0.25, 0.375);
  EXPECT_EQ(p.lo, 0.125);
  EXPECT_EQ(p.hi, 0.125);
}

TEST(RoundingTube, AprioriBoxContainsTheExactSpanAndRadius) {
  // W + [0, 1]·F with W = [−1, 1], F = [−2⁻⁵³, 2⁻⁵³]: exactly [−1 − 2⁻⁵³, 1 + 2⁻⁵³], which
  // round-to-nearest gives as [−1, 1].
  ASSERT_EQ(1.0 + 0x1p-53, 1.0);
  const ar::Box3 W{ar::Vec3::Constant(-1.0), ar::Vec3::Constant(1.0)};
  const ar::Box3 F{ar::Vec3::Constant(-0x1p-53), ar::Vec3::Constant(0x1p-53)};
  const ar::Box3 span = ar::apriori_span(W, F, ar::Interval(1.0));
  for (int k = 0; k < 3; ++k) {
    EXPECT_LT(span.lo(k), -1.0);
    EXPECT_GT(span.hi(k), 1.0);
  }
  // e_R + h·max_G‖ω‖ with G's corner (1, 2⁻²⁷, 0): exactly √(1 + 2⁻⁵⁴) > 1 for e_R = 0.
  const ar::Box3 G = rtt::point_box({1.0, rtt::tiny27, 0.0});
  ASSERT_EQ(G.norm_max(), 1.0);
  EXPECT_GT(ar::apriori_attitude_need(0.0, ar::Interval(1.0), G), 1.0);
  // h·max_G‖ω‖ = 0.7·0.7, whose product rounds down.
  const rtt::Exact sq = rtt::two_prod(0.7, 0.7);
  ASSERT_GT(sq.e, 0.0);
  const double need = ar::apriori_attitude_need(0.0, ar::Interval(0.7), rtt::point_box({0.7, 0.0, 0.0}));
  EXPECT_TRUE(rtt::at_least(need, sq));
  EXPECT_FALSE(rtt::at_least(0.7 * 0.7, sq));
}

TEST(RoundingTube, ComparisonMatrixEntriesBoundTheirFormulas) {
  // |A|'s first row (1, 2⁻²⁷, 0); B ∈ [−R, R] with R₀₀ = 1, R₀₁ = 2⁻²⁷, which contains
  // B = [[1, 2⁻²⁷, 0], 0, 0] with μ₂(B) = ½ + √(¼ + 2⁻⁵⁶) > 1; G's corner (1, 2⁻²⁷, 0). In
  // round-to-nearest every one of M's entries below is exactly 1.
  ar::Mat3 Arow = ar::Mat3::Zero();
  Arow(0, 0) = 1.0;
  Arow(0, 1) = rtt::tiny27;
  const ar::IntervalMat3 A = ar::IntervalMat3::point(Arow);
  const ar::IntervalMat3 B{-Arow, Arow};
  const ar::Box3 G = rtt::point_box({1.0, rtt::tiny27, 0.0});
  ASSERT_EQ(Arow.norm(), 1.0);
  ASSERT_EQ(attiguard::lie::lambda_max(B.center()) + B.radius().norm(), 1.0);
  const ar::Mat5 M = ar::comparison_matrix(A, B, G);
  EXPECT_GT(M(0, 4), 1.0);  // ‖row_0 |A|‖
  EXPECT_GT(M(3, 4), 1.0);  // ‖|A|‖_F
  EXPECT_GT(M(3, 3), 1.0);  // sup μ₂(B)
  EXPECT_GT(M(4, 4), 1.0);  // max_G ‖ω‖
  EXPECT_EQ(M(0, 1), rtt::tiny27);  // sup|B_01|: exact
  EXPECT_EQ(M(0, 0), 1.0);          // sup B_00: exact
  // μ₂'s bound is proved, not Gershgorin's: λ_max([[1, 1, 0], [1, −1, 0], 0]) = √2 (Gershgorin 2).
  ar::Mat3 S = ar::Mat3::Zero();
  S << 1.0, 1.0, 0.0, 1.0, -1.0, 0.0, 0.0, 0.0, 0.0;
  const double mu = ar::comparison_matrix(A, ar::IntervalMat3::point(S), G)(3, 3);
  EXPECT_GE(mu * mu, 2.0);
  EXPECT_LT(mu, std::sqrt(2.0) + 1e-12);
}

TEST(RoundingTube, ExpMetzlerUpperBoundsTheExactExponential) {
  // N nilpotent (Metzler): N₀₁ = N₁₂ = a = 1 + 2⁻³⁰, so exp(N) = I + N + N²/2 exactly and
  // exp(N)₀₂ = a²/2, whose product a² = 1 + 2⁻²⁹ + 2⁻⁶⁰ rounds down.
  const double a = 1.0 + 0x1p-30;
  ar::Mat5 N = ar::Mat5::Zero();
  N(0, 1) = a;
  N(1, 2) = a;
  const rtt::Exact sq = rtt::two_prod(a, a);
  ASSERT_GT(sq.e, 0.0);
  const Eigen::MatrixXd rtn = ar::expm(N);
  EXPECT_FALSE(rtt::at_least(2.0 * rtn(0, 2), sq));  // round-to-nearest is below the exact value
  const ar::Mat5 E = ar::exp_metzler_upper(N, ar::Interval(1.0));
  EXPECT_TRUE(rtt::at_least(2.0 * E(0, 2), sq));
  EXPECT_GE(E(0, 1), a);
  EXPECT_GE(E(0, 0), 1.0);
  EXPECT_LT(E(0, 2), 0.5 * a * a * (1.0 + 1e-13));  // and tight
  // A negative diagonal (the e^{−s} shift) and a duration interval: the bound holds for every
  // t ∈ [0.5, 1]: e^{−t} ≤ e^{−0.5}, e^{2t} ≤ e².
  ar::Mat5 D = ar::Mat5::Zero();
  D(0, 0) = -1.0;
  D(1, 1) = 2.0;
  const ar::Mat5 ED = ar::exp_metzler_upper(D, ar::Interval(0.5, 1.0));
  EXPECT_GE(ED(0, 0), std::exp(-0.5));
  EXPECT_GE(ED(1, 1), std::exp(2.0));
  EXPECT_LT(ED(1, 1), std::exp(2.0) * (1.0 + 1e-13));
  EXPECT_GE(ED(0, 1), 0.0);
  // E z + ε rounded up: 1·1 + 2⁻⁵³ > 1 exactly, 1 in round-to-nearest.
  const ar::Deviation::Vector z = ar::Deviation::Vector::Constant(1.0);
  const ar::Deviation::Vector eps = ar::Deviation::Vector::Constant(0x1p-53);
  EXPECT_EQ((ar::Mat5::Identity() * z + eps)(0), 1.0);
  EXPECT_GT(ar::apply_upper(ar::Mat5::Identity(), z, eps)(0), 1.0);
}

TEST(RoundingTube, TentBoundsContainTheExactTent) {
  // a = b = 1, slopes in [−2⁻⁵⁴, 2⁻⁵⁴], h = 1: the lines cross at ½, the tent's lower end is
  // exactly 1 − 2⁻⁵⁵ and its upper end 1 + 2⁻⁵⁵; round-to-nearest gives 1 for both.
  ASSERT_EQ(1.0 + 0.5 * -0x1p-54, 1.0);
  const ar::Interval h(1.0);
  EXPECT_LT(ar::tent_lower(1.0, 1.0, -0x1p-54, 0x1p-54, h), 1.0);
  EXPECT_GT(ar::tent_upper(1.0, 1.0, -0x1p-54, 0x1p-54, h), 1.0);
  // Tight where the tent is representable: a = b = 0, slopes in [−1, 1], h = 2: [−1, 1].
  const double lo = ar::tent_lower(0.0, 0.0, -1.0, 1.0, ar::Interval(2.0));
  EXPECT_LE(lo, -1.0);
  EXPECT_GT(lo, -1.0 - 1e-15);
  // Monotone slopes: the tent's lower end is the start value (0 → 1 with slopes in [1, 1]).
  EXPECT_LE(ar::tent_lower(0.0, 1.0, 1.0, 1.0, h), 0.0);
  EXPECT_GT(ar::tent_lower(0.0, 1.0, 1.0, 1.0, h), -1e-15);
  // The box ± deviation: [1, 1] ± 2⁻⁵⁴ is [1 − 2⁻⁵⁴, 1 + 2⁻⁵⁴]; round-to-nearest: [1, 1].
  ASSERT_EQ(1.0 - 0x1p-54, 1.0);
  const ar::Box3 b = ar::inflated_outward(rtt::point_box(ar::Vec3::Ones()), ar::Vec3::Constant(0x1p-54));
  EXPECT_LT(b.lo(0), 1.0);
  EXPECT_GT(b.hi(0), 1.0);
}

TEST(RoundingTube, OmegaNormBoundExceedsTheExactNorm) {
  // max‖ω*‖ over a tent with corner (1, 2⁻²⁷, 0) is √(1 + 2⁻⁵⁴) > 1 (computed: 1); 1 + 2⁻⁵³ > 1.
  EXPECT_GT(ar::omega_norm_upper(rtt::point_box({1.0, rtt::tiny27, 0.0}), 0.0), 1.0);
  EXPECT_GT(ar::omega_norm_upper(rtt::point_box({1.0, 0.0, 0.0}), 0x1p-53), 1.0);
  EXPECT_GT(ar::norm_max_upper(rtt::point_box({-1.0, -rtt::tiny27, 0.0})), 1.0);
  EXPECT_EQ(rtt::point_box({1.0, rtt::tiny27, 0.0}).norm_max() + 0.0, 1.0);  // round-to-nearest
}

TEST(RoundingTube, AttitudeHullDistanceExceedsTheExactAngle) {
  // I and the rotation by π/2 about z (entries 0, ±1: an exact rotation): d = π/2 exactly,
  // above the double nearest π/2, which round-to-nearest lie::distance returns.
  const ar::Mat3 I = ar::Mat3::Identity();
  ar::Mat3 Rz = ar::Mat3::Zero();
  Rz << 0.0, -1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0;
  const double half_pi = std::numbers::pi / 2.0;  // < π/2: the double π is below π
  EXPECT_LE(attiguard::lie::distance(I, Rz), half_pi);
  EXPECT_GT(ar::distance_upper(I, Rz), half_pi);
  EXPECT_LT(ar::distance_upper(I, Rz), half_pi * (1.0 + 1e-14));
  // Tight on a small rotation (where acos of the trace would lose half the digits).
  const double c = std::cos(1e-3);
  const double s = std::sin(1e-3);
  ar::Mat3 Rs = ar::Mat3::Identity();
  Rs(0, 0) = c;
  Rs(0, 1) = -s;
  Rs(1, 0) = s;
  Rs(1, 1) = c;
  EXPECT_NEAR(ar::distance_upper(I, Rs), 1e-3, 1e-15);
  EXPECT_GE(ar::distance_upper(I, Rs), attiguard::lie::distance(I, Rs));
}
