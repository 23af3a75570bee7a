// The RKMK stages' exp and dexpinv (lie::chart_coefficients, lie::times_exp,
// lie::apply_right_jacobian_inverse) against the formulas they replace, over ‖w‖ from 1e-12 to 30
// (docs/performance.md, "Lean core (issue 48, item 2)").
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <utility>

#include "attiguard/lie/jacobians.hpp"
#include "attiguard/lie/so3.hpp"
#include "test_support.hpp"

namespace attiguard::lie {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// ‖w‖ = 10^e for e from −12 to log10(30) in steps of 0.01, plus the series switch θ = 0.1.
template <class F>
void over_the_range(F&& f) {
  for (double e = -12.0; e <= std::log10(30.0); e += 0.01) {
    f(std::pow(10.0, e));
  }
  for (double t : {0.1 * (1.0 - 1e-15), 0.1, 0.1 * (1.0 + 1e-15), std::numbers::pi, 2.0 * std::numbers::pi - 1e-3}) {
    f(t);
  }
}

// a, b, c against long-double references that have no cancellation: sin θ/θ, 2 sin²(θ/2)/θ² and
// the series of c to θ¹⁶ (below θ = 0.1 the series; above, the closed forms of exp_coefficients,
// so the comparison there is exp_coefficients').
TEST(LieChartCoefficients, SeriesIsExactToDoublePrecisionBelowTheSwitch) {
  double worst = 0.0;
  over_the_range([&](double theta) {
    if (theta >= 0.1) return;
    const Vec3 w = theta * test::random_unit();
    const long double t = std::sqrt(static_cast<long double>(w.squaredNorm()));
    const long double t2 = t * t;
    const long double a = t < 1e-6L ? 1.0L - t2 / 6.0L : std::sin(t) / t;
    const long double s = std::sin(t / 2.0L);
    const long double b = t < 1e-6L ? 0.5L - t2 / 24.0L : 2.0L * s * s / t2;
    const long double coef[] = {1.0L / 12, 1.0L / 720, 1.0L / 30240, 1.0L / 1209600, 1.0L / 47900160,
                                691.0L / 1307674368000, 1.0L / 74724249600, 3617.0L / 10670622842880000};
    long double c = 0.0L;
    for (int n = 7; n >= 0; --n) c = c * t2 + coef[n];
    const ExpCoefficients k = chart_coefficients(w);
    for (const auto& [got, want] : {std::pair{k.a, a}, std::pair{k.b, b}, std::pair{k.c, c}}) {
      const double rel = static_cast<double>(std::abs((static_cast<long double>(got) - want) / want)) / kEps;
      worst = std::max(worst, rel);
    }
  });
  std::printf("[ measured ] chart_coefficients below theta = 0.1: worst %.2f ulp of a, b, c\n", worst);
  EXPECT_LE(worst, 2.0);
}

// R exp(ŵ) as times_exp against R · exp(w), and J_r⁻¹(w) v as two cross products against the
// matrix right_jacobian_inverse(w) times v: relative to the size of the result's terms.
TEST(LieChartCoefficients, StageExpAndDexpinvAgreeWithTheMatrixFormulas) {
  double worst_exp = 0.0;
  double worst_dexpinv = 0.0;
  over_the_range([&](double theta) {
    for (int i = 0; i < 4; ++i) {
      const Vec3 w = theta * test::random_unit();
      const Mat3 R = test::random_rotation();
      const Vec3 v = test::random_vector_in_ball(1.0) + 0.5 * test::random_unit();
      const ExpCoefficients k = chart_coefficients(w);
      const Mat3 old_exp = R * exp(w);
      const Mat3 new_exp = times_exp(R, w, k.a, k.b);
      worst_exp = std::max(worst_exp, (new_exp - old_exp).cwiseAbs().maxCoeff() / kEps);
      const Vec3 old_v = right_jacobian_inverse(w) * v;
      const Vec3 new_v = apply_right_jacobian_inverse(w, k.c, v);
      const double scale = v.norm() * (1.0 + 0.5 * theta + std::abs(k.c) * theta * theta);
      worst_dexpinv = std::max(worst_dexpinv, (new_v - old_v).norm() / (scale * kEps));
    }
  });
  std::printf("[ measured ] times_exp against R exp(w): worst %.2f ulp; apply_right_jacobian_inverse: %.2f ulp\n",
              worst_exp, worst_dexpinv);
  EXPECT_LE(worst_exp, 8.0);
  EXPECT_LE(worst_dexpinv, 8.0);
}

// Near a half turn the product stays a rotation to rounding (no re-projection anywhere).
TEST(LieChartCoefficients, TimesExpIsARotationNearZeroAndPi) {
  for (double theta : {0.0, 1e-300, 1e-12, 1e-4, 0.0999, 0.1, 1.0, std::numbers::pi - 1e-9, std::numbers::pi}) {
    const Vec3 w = theta * test::random_unit();
    const ExpCoefficients k = chart_coefficients(w);
    const Mat3 R = test::random_rotation();
    const Mat3 E = times_exp(R, w, k.a, k.b);
    EXPECT_LT(orthonormality_error(E), 4e-15) << theta;
    EXPECT_LT((R.transpose() * E - exp(w)).norm(), 4e-15) << theta;
  }
}

}  // namespace
}  // namespace attiguard::lie
