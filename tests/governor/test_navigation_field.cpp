// The navigation field of the PET-ERG paper (Sec. III-B.2): analytic gradients against finite
// differences along R_g exp(εη̂), and the properties the repulsive potential must have.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "attiguard/governor/navigation_field.hpp"
#include "test_support.hpp"

namespace attiguard::governor {
namespace {

using lie::Mat3;
using lie::Vec3;

/// Gradient (body vector) of f at R by central differences of f(R exp(εη̂)).
template <class F>
Vec3 fd_gradient(F&& f, const Mat3& R, double h = 1e-6) {
  Vec3 g;
  for (int i = 0; i < 3; ++i) {
    const Vec3 e = Vec3::Unit(i);
    g(i) = (f(R * lie::exp(h * e)) - f(R * lie::exp(-h * e))) / (2.0 * h);
  }
  return g;
}


TEST(NavigationField, AttractiveFieldIsMinusTheGradientOfPa) {
  for (int i = 0; i < 200; ++i) {
    const Mat3 R_g = test::random_rotation();
    const Mat3 R_d = test::random_rotation();
    const Vec3 fd = fd_gradient([&](const Mat3& R) { return attractive_potential(R, R_d); }, R_g);
    EXPECT_LE((attractive_field(R_g, R_d) + fd).norm(), 1e-8);
  }
  EXPECT_LE(attractive_field(Mat3::Identity(), Mat3::Identity()).norm(), 0.0);
}

TEST(NavigationField, ConstraintGradientMatchesFiniteDifferencesAndHasNormSinBeta) {
  for (int i = 0; i < 200; ++i) {
    const ConeConstraint cone = keep_in_cone(test::random_unit(), test::random_unit(), 2.0);
    const Mat3 R_g = test::random_rotation();
    const Vec3 fd = fd_gradient([&](const Mat3& R) { return cone_cosine(cone, R); }, R_g);
    const Vec3 g = constraint_gradient(cone, R_g);
    EXPECT_LE((g - fd).norm(), 1e-8);
    const double c = cone_cosine(cone, R_g);
    EXPECT_NEAR(g.norm(), std::sqrt(std::max(0.0, 1.0 - c * c)), 1e-12);
  }
}

TEST(NavigationField, RepulsiveGradientMatchesFiniteDifferences) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int active = 0;
  for (int i = 0; i < 2000 && active < 300; ++i) {
    const ConeConstraint cone =
        keep_out_cone(test::random_unit(), test::random_unit(), 0.2 + u(test::rng()), 0.2, 0.3, 0.5 + u(test::rng()));
    const Mat3 R_g = test::random_rotation();
    const double c = cone_cosine(cone, R_g);
    if (!(c > cone.delta + 1e-3 && c < cone.zeta)) {
      continue;
    }
    ++active;
    const Vec3 fd = fd_gradient([&](const Mat3& R) { return repulsive_potential(cone, R); }, R_g, 1e-7);
    const Vec3 rho_r = repulsive_field(cone, R_g);
    EXPECT_LE((rho_r + fd).norm(), 1e-6 * std::max(1.0, fd.norm())) << "c = " << c;
    // The field pushes c up (away from the cone): dc = g_cᵀρ_r ≥ 0.
    EXPECT_GE(constraint_gradient(cone, R_g).dot(rho_r), 0.0);
  }
  EXPECT_GE(active, 100);
}

TEST(NavigationField, RepulsivePotentialIsC1AtZetaAndDivergesAtDelta) {
  const ConeConstraint cone = keep_in_cone(Vec3(0, 0, 1), Vec3(1, 0, 0), 2.5);
  const double h = 1e-7;
  EXPECT_EQ(repulsive_potential_of_cosine(cone, cone.zeta), 0.0);
  EXPECT_EQ(repulsive_potential_of_cosine(cone, cone.zeta + 0.1), 0.0);
  EXPECT_NEAR(repulsive_potential_slope(cone, cone.zeta - h), 0.0, 1e-5);
  // dP_r/dc against a difference quotient of P_r.
  for (double c = cone.delta + 1e-3; c < cone.zeta; c += 0.004) {
    const double fd = (repulsive_potential_of_cosine(cone, c + h) -
                       repulsive_potential_of_cosine(cone, c - h)) / (2.0 * h);
    EXPECT_NEAR(repulsive_potential_slope(cone, c), fd, 1e-5 * std::max(1.0, std::abs(fd)));
  }
  EXPECT_GT(repulsive_potential_of_cosine(cone, cone.delta + 1e-9), 1e6);
  // Finite (no ±∞/NaN) even outside the domain.
  EXPECT_TRUE(std::isfinite(repulsive_potential_of_cosine(cone, cone.delta - 0.1)));
  EXPECT_TRUE(std::isfinite(repulsive_potential_slope(cone, cone.delta - 0.1)));
}

TEST(NavigationField, TotalFieldIsMinusTheGradientOfTheTotalPotential) {
  ConeSet cones;
  cones.push_back(keep_out_cone(Vec3(0, 0, 1), Vec3(1, 0, 0), 0.4, 0.2, 0.4));
  cones.push_back(keep_out_cone(Vec3(1, 0, 0), Vec3(0, 0, 1), 0.3, 0.2, 0.4));
  int tested = 0;
  for (int i = 0; i < 3000 && tested < 200; ++i) {
    const Mat3 R_g = test::random_rotation();
    const Mat3 R_d = test::random_rotation();
    bool inside = true;
    for (const ConeConstraint& c : cones) {
      inside = inside && cone_cosine(c, R_g) > c.delta + 1e-2;
    }
    if (!inside) {
      continue;
    }
    ++tested;
    const Vec3 fd = fd_gradient(
        [&](const Mat3& R) { return navigation_potential(cones.span(), R, R_d); }, R_g, 1e-7);
    const Vec3 rho = navigation_field(cones.span(), R_g, R_d);
    EXPECT_LE((rho + fd).norm(), 1e-6 * std::max(1.0, fd.norm()));
  }
  EXPECT_GE(tested, 100);
}

// docs/pet-erg.md, section 4, "Half-turns": at θ = d(R_g, R_d) = π the attraction sk(R_gᵀR_d)^∨
// vanishes (P_a's maximum), so the field the governor follows keeps a floor there.
TEST(NavigationField, TheGovernedAttractionLeavesAnExactHalfTurn) {
  const double floor = 0.05;
  for (const Vec3& axis : {Vec3(0.0, 0.0, 1.0), Vec3(1.0, 0.0, 0.0), Vec3(0.0, 1.0, 0.0)}) {
    Mat3 R_d = -Mat3::Identity();
    R_d += 2.0 * axis * axis.transpose();  // exactly π about a coordinate axis
    const Mat3 R_g = Mat3::Identity();
    ASSERT_EQ(attractive_field(R_g, R_d).norm(), 0.0);  // the paper's field holds R_g there for ever
    const Vec3 rho = governed_attractive_field(R_g, R_d, floor);
    EXPECT_NEAR(rho.norm(), floor, 1e-15);
    EXPECT_NEAR(std::abs(rho.normalized().dot(axis)), 1.0, 1e-12);
    // a step along it is a descent of P_a (the angle to R_d decreases)
    const Mat3 moved = R_g * lie::exp(1e-3 * rho.normalized());
    EXPECT_LT(attractive_potential(moved, R_d), attractive_potential(R_g, R_d));
    EXPECT_LT(lie::distance(moved, R_d), std::numbers::pi - 0.9e-3);
  }
}

TEST(NavigationField, TheGovernedAttractionIsThePapersAwayFromHalfTurnsAndContinuous) {
  const double floor = 0.05;
  for (int i = 0; i < 500; ++i) {
    const Mat3 R_g = test::random_rotation();
    const Mat3 R_d = test::random_rotation();
    const Vec3 paper = attractive_field(R_g, R_d);
    const Vec3 governed = governed_attractive_field(R_g, R_d, floor);
    if (paper.norm() >= floor || lie::distance(R_g, R_d) <= 0.5 * std::numbers::pi) {
      EXPECT_EQ((governed - paper).norm(), 0.0);
    } else {
      EXPECT_NEAR(governed.norm(), floor, 1e-12);
    }
    EXPECT_EQ((governed_attractive_field(R_g, R_d, 0.0) - paper).norm(), 0.0);
  }
  // continuous where sin θ crosses the floor, beyond a quarter turn
  const Vec3 axis = Vec3(0.3, -0.5, 0.8).normalized();
  const double theta_edge = std::numbers::pi - std::asin(floor);
  const Vec3 inside = governed_attractive_field(Mat3::Identity(), lie::exp((theta_edge + 1e-9) * axis), floor);
  const Vec3 outside = governed_attractive_field(Mat3::Identity(), lie::exp((theta_edge - 1e-9) * axis), floor);
  EXPECT_LE((inside - outside).norm(), 1e-8);
  // below a quarter turn a small field is the paper's (R_g near R_d)
  const Mat3 near = lie::exp(1e-4 * axis);
  EXPECT_EQ((governed_attractive_field(Mat3::Identity(), near, floor) - attractive_field(Mat3::Identity(), near)).norm(),
            0.0);
}

}  // namespace
}  // namespace attiguard::governor
