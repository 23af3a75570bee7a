// Rounding sites of the LMI vertex data (docs/reach.md, "Rounding sites"): the verified enclosure
// of J⁻¹, the vertex radii, the upward chord of the A-deviation bound. Constructed cases where the
// round-to-nearest value proves a wrong statement (truth in long double, refined), refused now;
// ordinary loops still prove.

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/SVD>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <random>
#include <vector>

#include "attiguard/lie/so3.hpp"
#include "attiguard/reach/closed_loop.hpp"
#include "attiguard/reach/contraction_sdp.hpp"
#include "attiguard/reach/lmi_proof.hpp"

namespace ar = attiguard::reach;

namespace rounding_vertex_test {

static_assert(std::numeric_limits<long double>::digits >= 64, "the truth needs extended precision");

using Mat3L = Eigen::Matrix<long double, 3, 3>;
using Mat6L = Eigen::Matrix<long double, 6, 6>;

/// J = V diag(1e-6, 1, 1) Vᵀ rounded and symmetrised (exactly symmetric floats): κ ≈ 1e6, a
/// physical body (1e-6 + 1 ≥ 1).
ar::Mat3 ill_conditioned_inertia(std::uint64_t seed) {
  std::mt19937_64 g(seed);
  std::normal_distribution<double> n(0.0, 1.0);
  const ar::Mat3 V = attiguard::lie::exp(ar::Vec3(n(g), n(g), n(g)));
  const ar::Mat3 J = V * ar::Vec3(1e-6, 1.0, 1.0).asDiagonal() * V.transpose();
  return 0.5 * (J + J.transpose());
}

/// The exact J⁻¹ to ~1e-13 relative: the long-double inverse, refined twice by Y += Y (I − J Y).
Mat3L true_inverse(const ar::Mat3& J) {
  const Mat3L Jl = J.cast<long double>();
  Mat3L Y = Jl.inverse();
  for (int k = 0; k < 2; ++k) Y += Y * (Mat3L::Identity() - Jl * Y);
  return Y;
}

/// λ_max of F + Fᵀ − 2cI (the LMI with M = I) for F = [[0, I], [−Y, −Y]] (the PD loop with
/// k_p = k_d = 1, R = R_g, ω = 0: A = −J⁻¹, B = −J⁻¹), in long double.
long double lmi_lambda_max(const Mat3L& Y, long double c) {
  Mat6L F = Mat6L::Zero();
  F.topRightCorner<3, 3>() = Mat3L::Identity();
  F.bottomLeftCorner<3, 3>() = -Y;
  F.bottomRightCorner<3, 3>() = -Y;
  const Mat6L L = F + F.transpose() - 2.0L * c * Mat6L::Identity();
  const Eigen::SelfAdjointEigenSolver<Mat6L> es(0.5L * (L + L.transpose()), Eigen::EigenvaluesOnly);
  return es.eigenvalues()(5);
}

/// The rate c* at which λ_max crosses zero (λ_max decreases in c), by bisection.
long double threshold(const Mat3L& Y) {
  long double lo = 0.0L;
  long double hi = 1e7L;
  for (int it = 0; it < 200; ++it) {
    const long double mid = 0.5L * (lo + hi);
    (lmi_lambda_max(Y, mid) > 0.0L ? lo : hi) = mid;
  }
  return hi;
}

}  // namespace rounding_vertex_test

namespace rvt = rounding_vertex_test;

TEST(RoundingVertex, InverseEnclosureContainsTheExactInverseTheFloatInverseMisses) {
  // rounding site: j-inverse
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const ar::Mat3 J = rvt::ill_conditioned_inertia(seed);
    const rvt::Mat3L Y = rvt::true_inverse(J);
    const ar::Mat3 X = J.inverse();
    // The float inverse is off by ~κε‖J⁻¹‖ ≈ 1e-4, far above the truth's error (~1e-13 relative).
    EXPECT_GT((X.cast<long double>() - Y).cwiseAbs().maxCoeff(), 1e-8L) << seed;
    const ar::IntervalMat3 enc = ar::enclose_inverse(J);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        EXPECT_LE(static_cast<long double>(enc.lo(i, j)), Y(i, j)) << seed;
        EXPECT_GE(static_cast<long double>(enc.hi(i, j)), Y(i, j)) << seed;
      }
    }
    EXPECT_LT(enc.radius().maxCoeff(), 1e-6 * Y.cwiseAbs().maxCoeff());  // tight, not vacuous
  }
}

TEST(RoundingVertex, LmiProvedAtTheFloatVertexButFalseForTheTrueDataIsRefused) {
  // rounding site: vertex-data. The PD loop with an ill-conditioned J at ω = 0, R = R_g (radius 0):
  // A = B = −J⁻¹. Between the rate threshold c*_f of the float data and c*_t of the exact data,
  // the LMI holds for the float numbers and fails for the true ones.
  std::optional<std::uint64_t> found;
  long double cf = 0.0L;
  long double ct = 0.0L;
  for (std::uint64_t seed = 1; seed <= 40 && !found; ++seed) {
    const ar::Mat3 J = rvt::ill_conditioned_inertia(seed);
    const ar::PdLoop loop(J, 1.0, 1.0, ar::Mat3::Identity());
    const ar::LmiEnclosure enc = loop.lmi_enclosure({ar::Mat3::Identity(), 0.0}, ar::Box3{});
    cf = rvt::threshold(-enc.vertices.front().A.cast<long double>());
    ct = rvt::threshold(rvt::true_inverse(J));
    if (ct > cf * (1.0L + 1e-12L)) found = seed;
  }
  ASSERT_TRUE(found.has_value());
  const ar::Mat3 J = rvt::ill_conditioned_inertia(*found);
  const ar::PdLoop loop(J, 1.0, 1.0, ar::Mat3::Identity());
  const ar::LmiEnclosure enc = loop.lmi_enclosure({ar::Mat3::Identity(), 0.0}, ar::Box3{});
  // ρ only covers the float centre's orthogonality defect (~1e-16, times ‖J⁻¹‖ ≈ 1e6).
  ASSERT_GT(enc.rho, 0.0);
  ASSERT_LT(enc.rho, 1e-6);
  const std::vector<double> mu(enc.vertices.size(), 1e9);  // μρ² and 1/μ both ≤ 1e-9
  const double c = static_cast<double>(0.5L * (cf + ct));
  // The statement is wrong: the exact LMI at c has a positive eigenvalue.
  EXPECT_GT(rvt::lmi_lambda_max(rvt::true_inverse(J), c), 0.0L);
  // Round-to-nearest (the vertex data as exact numbers, ρ = 2 sin(0) = 0) proves it.
  ar::LmiEnclosure unrounded = enc;
  unrounded.rho = 0.0;
  for (ar::LmiVertex& v : unrounded.vertices) {
    v.A_rad.setZero();
    v.B_rad.setZero();
  }
  const ar::Mat3 I = ar::Mat3::Identity();
  EXPECT_TRUE(ar::prove_contraction_lmi(unrounded, I, I, c, {}).proved);
  // The vertex radii refuse it (with or without ρ), and prove a rate comfortably above the
  // exact threshold.
  EXPECT_FALSE(ar::prove_contraction_lmi(enc, I, I, c, mu).proved);
  ar::LmiEnclosure radii_only = enc;
  radii_only.rho = 0.0;
  EXPECT_FALSE(ar::prove_contraction_lmi(radii_only, I, I, c, {}).proved);
  EXPECT_TRUE(ar::prove_contraction_lmi(enc, I, I, static_cast<double>(ct * (1.0L + 1e-6L)), mu).proved);
}

TEST(RoundingVertex, ChordIsRoundedUpWhereTheFloatSineIsBelowTheTruth) {
  // rounding site: chord (the A-deviation bound ρ). Radii where the float 2 sin(ρ/2) is below the
  // exact one (sinl: ~1e-19 relative): the round-to-nearest chord is not an upper bound.
  int found = 0;
  for (int k = 1; k < 2000 && found < 20; ++k) {
    const double rho = 1e-3 * k;
    const long double truth = 2.0L * std::sin(0.5L * static_cast<long double>(rho));
    if (truth - static_cast<long double>(ar::chord(rho)) < 1e-17L * truth) continue;
    ++found;
    EXPECT_GE(static_cast<long double>(ar::chord_up(rho)), truth) << rho;
    EXPECT_LE(ar::chord_up(rho), rho);
  }
  EXPECT_EQ(found, 20);
}

TEST(RoundingVertex, DeviationBoundCoversTheSampledDeviationAndOrdinaryLoopsStillProve) {
  // rounding site: a-deviation. ρ bounds ‖A(R) − A(R_c)‖₂ over the ball, with R_c a float rotation;
  // and the PD loop of the examples still proves its LMI with the vertex radii (they are ~1e-16).
  const ar::PdLoop loop(ar::Vec3(1.0, 2.0, 3.0).asDiagonal(), 2.0, 3.0, attiguard::lie::exp(ar::Vec3(0.1, 0.2, 0.3)));
  std::mt19937_64 g(4747);
  std::normal_distribution<double> n(0.0, 1.0);
  const ar::AttitudeBall att{attiguard::lie::exp(ar::Vec3(0.3, -0.2, 0.1)), 0.05};
  const double rho = loop.a_deviation_bound(att);
  const ar::Mat3 Ac = loop.A(att.center, ar::Vec3::Zero());
  for (int k = 0; k < 200; ++k) {
    const ar::Vec3 eta = ar::Vec3(n(g), n(g), n(g)).normalized() * att.radius;
    const Eigen::JacobiSVD<ar::Mat3> svd(loop.A(att.center * attiguard::lie::exp(eta), ar::Vec3::Zero()) - Ac);
    EXPECT_LE(svd.singularValues()(0), rho);
  }
  const ar::LmiEnclosure enc = loop.lmi_enclosure(att, {ar::Vec3(0.05, -0.1, 0.0), ar::Vec3(0.15, 0.0, 0.1)});
  for (const ar::LmiVertex& v : enc.vertices) {
    EXPECT_GT(v.A_rad.maxCoeff(), 0.0);  // A(R_c) is not exact in floating point
    EXPECT_LT(v.A_rad.maxCoeff(), 1e-14);
    EXPECT_LT(v.B_rad.maxCoeff(), 1e-14);
  }
  ar::MetricSdpSettings coupled;
  coupled.coupled = true;
  const ar::StateMetric I{ar::Mat3::Identity(), ar::Mat3::Zero(), ar::Mat3::Identity()};
  const ar::MetricSolution sol = ar::solve_metric(enc, I, -0.2, ar::MetricObjective::max_min_eigenvalue, coupled);
  ASSERT_TRUE(sol.ok) << sol.message;
  EXPECT_TRUE(sol.proved);
}

TEST(RoundingVertex, SpectralNormOfTheInverseIsBoundedAboveWhereTheFloatEigenvalueIsTooLarge) {
  // rounding site: j-inverse-norm. ‖J⁻¹‖₂ = 1/λ_min(J); the floating-point λ_min of an
  // ill-conditioned J is off by ~ε‖J‖ ≈ 1e-10 relative, above the truth for some seeds: 1/λ̃ is
  // then below ‖J⁻¹‖₂ (the truth from a long-double eigensolver, ~1e-13 relative).
  int found = 0;
  for (std::uint64_t seed = 1; seed <= 40 && found < 3; ++seed) {
    const ar::Mat3 J = rvt::ill_conditioned_inertia(seed);
    const Eigen::SelfAdjointEigenSolver<rvt::Mat3L> es(J.cast<long double>(), Eigen::EigenvaluesOnly);
    const long double truth = 1.0L / es.eigenvalues()(0);
    const double lambda_float = Eigen::SelfAdjointEigenSolver<ar::Mat3>(J, Eigen::EigenvaluesOnly).eigenvalues()(0);
    if (!(1.0L / static_cast<long double>(lambda_float) < truth * (1.0L - 1e-12L))) continue;
    ++found;
    const double bound = ar::inverse_spectral_bound(J);
    EXPECT_GE(static_cast<long double>(bound), truth) << seed;
    EXPECT_LT(static_cast<long double>(bound), truth * (1.0L + 1e-6L)) << seed;  // not vacuous
  }
  EXPECT_EQ(found, 3);
}

TEST(RoundingVertex, TubeEnclosuresContainTheExactMatricesTheFloatOnesMiss) {
  // rounding sites: gyroscopic-basis, gyroscopic-enclosure, b-enclosure, a-enclosure. Over a point
  // (ρ = 0, a point box) the enclosures of before were the float A(R_c), B(ω): an ill-conditioned J
  // puts the exact matrices (long double, exact inverse) ~1e-4 away from them.
  const ar::Mat3 J = rvt::ill_conditioned_inertia(3);
  const rvt::Mat3L Y = rvt::true_inverse(J);
  const rvt::Mat3L Jl = J.cast<long double>();
  const ar::Vec3 w(0.3, -0.2, 0.5);
  const ar::Box3 box{w, w};
  const ar::AttitudeBall att{attiguard::lie::exp(ar::Vec3(0.2, 0.1, -0.3)), 0.0};
  const ar::Mat3 Rg = attiguard::lie::exp(ar::Vec3(-0.1, 0.4, 0.2));
  const ar::PdLoop pd(J, 2.0, 3.0, Rg);
  const ar::RigidBodyLoop torque_free(J, ar::Vec3::Zero());
  auto hat = [](const Eigen::Matrix<long double, 3, 1>& v) {
    rvt::Mat3L H;
    H << 0.0L, -v(2), v(1), v(2), 0.0L, -v(0), -v(1), v(0), 0.0L;
    return H;
  };
  const Eigen::Matrix<long double, 3, 1> wl = w.cast<long double>();
  const rvt::Mat3L gyro = Y * (hat(Jl * wl) - hat(wl) * Jl);
  const rvt::Mat3L E = att.center.cast<long double>().transpose() * Rg.cast<long double>();
  const rvt::Mat3L A_true = -1.0L * Y * (E.trace() * rvt::Mat3L::Identity() - E);  // −(k_p/2), k_p = 2
  const rvt::Mat3L B_true = gyro - 3.0L * Y;
  auto contains = [](const ar::IntervalMat3& enc, const rvt::Mat3L& M) {
    return (enc.lo.cast<long double>().array() <= M.array()).all() &&
           (enc.hi.cast<long double>().array() >= M.array()).all();
  };
  EXPECT_TRUE(contains(torque_free.B_enclosure(att, box), gyro));
  EXPECT_TRUE(contains(pd.B_enclosure(att, box), B_true));
  EXPECT_TRUE(contains(pd.A_enclosure(att, box), A_true));
  EXPECT_FALSE(contains(ar::IntervalMat3::point(pd.B(att.center, w)), B_true));
  EXPECT_FALSE(contains(ar::IntervalMat3::point(pd.A(att.center, w)), A_true));
  // And the vertex data: the exact matrices lie within the radii.
  const ar::LmiEnclosure enc = pd.lmi_enclosure(att, box);
  for (const ar::LmiVertex& v : enc.vertices) {
    EXPECT_TRUE(contains(ar::IntervalMat3::around(v.A, v.A_rad), A_true));
    EXPECT_TRUE(contains(ar::IntervalMat3::around(v.B, v.B_rad), B_true));
  }
}
