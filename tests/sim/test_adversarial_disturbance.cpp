// The adversarial disturbance torque (sim/adversarial_disturbance.hpp; docs/pet-erg.md,
// section 11, "Adversarial disturbance"): within the bound, and the worst case of each aim
// against 1000 random torques of the ball, with V̇ and m̈ computed here by finite differences
// along the dynamics, independently of the formulas of the law.

#include <gtest/gtest.h>

#include <random>
#include <type_traits>
#include <vector>

#include "attiguard/control/pd_so3.hpp"
#include "attiguard/governor/cone_constraint.hpp"
#include "attiguard/lie/so3.hpp"
#include "attiguard/sim/adversarial_disturbance.hpp"
#include "test_support.hpp"

namespace attiguard::sim {
namespace {

using governor::ConeConstraint;
using lie::Mat3;
using lie::Vec3;

static_assert(noexcept(adversarial_torque(std::declval<const AdversaryModel&>(),
                                          std::declval<const Mat3&>(), std::declval<const Vec3&>(),
                                          std::declval<const Mat3&>())));

/// A random symmetric positive definite inertia, principal moments in [1, 5].
Mat3 random_inertia() {
  std::uniform_real_distribution<double> u(1.0, 5.0);
  const Mat3 Q = test::random_rotation();
  return Q * Vec3(u(test::rng()), u(test::rng()), u(test::rng())).asDiagonal() * Q.transpose();
}

/// One to three random keep-in cones that R satisfies (margin ≥ 0).
std::vector<ConeConstraint> random_cones(const Mat3& R_ib) {
  std::uniform_int_distribution<int> count(1, 3);
  std::uniform_real_distribution<double> angle(0.5, 3.0);
  std::vector<ConeConstraint> cones;
  const int n = count(test::rng());
  while (static_cast<int>(cones.size()) < n) {
    const ConeConstraint c = governor::keep_in_cone(test::random_vector_in_ball(1.0),
                                                    test::random_vector_in_ball(1.0),
                                                    angle(test::rng()));
    if (governor::pointing_margin(c, R_ib) > 0.0) cones.push_back(c);
  }
  return cones;
}

/// A state of the PD loop (3) with the disturbance d, and its time derivative.
struct Plant {
  Mat3 J;
  Mat3 R_g;
  control::PdGains gains{5.0, 1.0};
  /// ω̇ = J⁻¹((Jω) × ω + τ + d), τ of the PD law (3) (PET-ERG paper, eq. (1)).
  [[nodiscard]] Vec3 omega_dot(const Mat3& R, const Vec3& w, const Vec3& d) const {
    return J.inverse() * ((J * w).cross(w) + control::pd_torque(R, w, R_g, gains) + d);
  }
};

/// V(t) along the dynamics, by a central difference of V over ±h with the state moved to first
/// order (R exp(±h ω̂), ω ± h ω̇): exact to O(h²) for V̇.
double V_dot(const Plant& p, const Mat3& R, const Vec3& w, const Vec3& d, double h = 1e-5) {
  const Vec3 wd = p.omega_dot(R, w, d);
  auto V = [&](double s) {
    return control::pd_lyapunov(p.J, R * lie::exp(s * w), w + s * wd, p.R_g, p.gains);
  };
  return (V(h) - V(-h)) / (2.0 * h);
}

/// m̈ of a cone's margin along the dynamics: central difference over ±h2 of ṁ, itself a central
/// difference over ±h1 of the margin along R exp(s ω̂).
double margin_ddot(const Plant& p, const ConeConstraint& cone, const Mat3& R, const Vec3& w,
                   const Vec3& d) {
  const double h1 = 1e-5;
  const double h2 = 1e-4;
  auto m_dot = [&](const Mat3& Rs, const Vec3& ws) {
    return (governor::pointing_margin(cone, Rs * lie::exp(h1 * ws)) -
            governor::pointing_margin(cone, Rs * lie::exp(-h1 * ws))) /
           (2.0 * h1);
  };
  const Vec3 wd = p.omega_dot(R, w, d);
  return (m_dot(R * lie::exp(h2 * w), w + h2 * wd) - m_dot(R * lie::exp(-h2 * w), w - h2 * wd)) /
         (2.0 * h2);
}

TEST(AdversarialDisturbance, StaysWithinTheBoundAndReachesItAtEveryNonDegenerateState) {
  for (int trial = 0; trial < 500; ++trial) {
    const Mat3 J = random_inertia();
    const Mat3 R = test::random_rotation();
    const Mat3 R_g = test::random_rotation();
    const std::vector<ConeConstraint> cones = trial % 3 == 0 ? std::vector<ConeConstraint>{}
                                                             : random_cones(R);
    const double bound = 0.01 + 0.1 * (trial % 7);
    const double weight = (trial % 11) / 10.0;
    const Vec3 w = trial % 5 == 0 ? Vec3(Vec3::Zero()) : test::random_vector_in_ball(0.5);
    const Vec3 d = adversarial_torque(R, w, R_g, J, cones, bound, weight);
    ASSERT_TRUE(d.allFinite()) << trial;
    EXPECT_LE(d.norm(), bound * (1.0 + 1e-12)) << trial;
    EXPECT_NEAR(d.norm(), bound, 1e-12 * bound) << trial;
  }
  // Fully degenerate for aim (a): at rest on the reference, V̈ = dᵀJ⁻¹d is largest along J's
  // minor axis.
  const Mat3 J = Vec3(3.0, 1.0, 2.0).asDiagonal();
  const Vec3 d =
      adversarial_torque(Mat3::Identity(), Vec3::Zero(), Mat3::Identity(), J, {}, 0.2, 1.0);
  EXPECT_NEAR(std::abs(d.y()), 0.2, 1e-15);
}

TEST(AdversarialDisturbance, WithWeightOneItMaximisesVDotAmongRandomTorquesOfTheBall) {
  for (int trial = 0; trial < 20; ++trial) {
    Plant p;
    p.J = random_inertia();
    p.R_g = test::random_rotation();
    const Mat3 R = test::random_rotation();
    const Vec3 w = test::random_vector_in_ball(0.5);
    const std::vector<ConeConstraint> cones = random_cones(R);
    const double bound = 0.05;
    const Vec3 d = adversarial_torque(R, w, p.R_g, p.J, cones, bound, 1.0);
    const double best = V_dot(p, R, w, d);
    double best_random = -1e300;
    for (int i = 0; i < 1000; ++i) {
      const double v = V_dot(p, R, w, test::random_vector_in_ball(bound));
      EXPECT_LE(v, best + 1e-8) << trial << " " << i;
      best_random = std::max(best_random, v);
    }
    // The comparison can fail: the best random torque comes close to the adversary.
    EXPECT_GT(best_random, best - 0.2 * bound * w.norm()) << trial;
  }
}

TEST(AdversarialDisturbance, WithWeightZeroItMinimisesTheNearestConesMarginAcceleration) {
  for (int trial = 0; trial < 20; ++trial) {
    Plant p;
    p.J = random_inertia();
    p.R_g = test::random_rotation();
    const Mat3 R = test::random_rotation();
    const Vec3 w = test::random_vector_in_ball(0.5);
    const std::vector<ConeConstraint> cones = random_cones(R);
    const int i = nearest_cone(cones, R);
    ASSERT_GE(i, 0);
    for (const ConeConstraint& c : cones) {
      EXPECT_GE(governor::pointing_margin(c, R),
                governor::pointing_margin(cones[static_cast<std::size_t>(i)], R));
    }
    const ConeConstraint& cone = cones[static_cast<std::size_t>(i)];
    const double bound = 0.05;
    const Vec3 d = adversarial_torque(R, w, p.R_g, p.J, cones, bound, 0.0);
    const double worst = margin_ddot(p, cone, R, w, d);
    for (int k = 0; k < 1000; ++k) {
      EXPECT_GE(margin_ddot(p, cone, R, w, test::random_vector_in_ball(bound)), worst - 1e-6)
          << trial << " " << k;
    }
    // And it lowers m̈ against no disturbance (the direction's sign is right).
    const Vec3 v = cone.axis_b.cross(R.transpose() * cone.direction_i);
    EXPECT_LT(worst, margin_ddot(p, cone, R, w, Vec3::Zero()) - 0.5 * bound * (p.J.inverse() * v).norm())
        << trial;
  }
}

TEST(AdversarialDisturbance, AtRestItPushesAlongInverseInertiaTimesTheAttitudeError) {
  // ω = 0: V̇ = ωᵀd = 0 for every d, V̈ = dᵀJ⁻¹(k_p s + d): to first order in d̄/(k_p‖s‖) the
  // maximiser is unit(J⁻¹s), not the "away from R_g" direction −s.
  Plant p;
  p.J = random_inertia();
  p.R_g = lie::exp(Vec3(0.3, -0.2, 0.5));
  const Mat3 R = Mat3::Identity();
  const double bound = 1e-3;
  const Vec3 d = adversarial_torque(R, Vec3::Zero(), p.R_g, p.J, {}, bound, 1.0);
  const Vec3 s = lie::vee(lie::sk(R.transpose() * p.R_g));
  EXPECT_LT((d - bound * (p.J.inverse() * s).normalized()).norm(), 1e-15);
  // V̈ by a central difference of V̇ along the trajectory from rest (ω(±h) = ±h ω̇).
  auto V_ddot = [&](const Vec3& dist) {
    const double h = 1e-4;
    const Vec3 wd = p.omega_dot(R, Vec3::Zero(), dist);
    return (V_dot(p, R * lie::exp(0.5 * h * h * wd), h * wd, dist) -
            V_dot(p, R * lie::exp(0.5 * h * h * wd), -h * wd, dist)) /
           (2.0 * h);
  };
  const double adversary = V_ddot(d);
  EXPECT_GT(adversary, V_ddot(-bound * s.normalized()));
  // First order: the d̄² term dᵀJ⁻¹d lets a direction tilted towards J's minor axis gain a
  // relative O(d̄ λ_max(J⁻¹)/(k_p‖J⁻¹s‖)) ≈ 1e-3 at most.
  for (int k = 0; k < 1000; ++k) {
    EXPECT_LE(V_ddot(test::random_vector_in_ball(bound)), adversary * (1.0 + 1e-3)) << k;
  }
}

}  // namespace
}  // namespace attiguard::sim
