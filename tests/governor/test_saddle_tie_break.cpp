// The saddle tie-break of the navigation field (docs/pet-erg.md, section 4, "Saddles: the
// tie-break"; src/attiguard/governor/saddle_tie_break.hpp): the detour direction, detection at
// an exactly symmetric saddle, no detection elsewhere, release, and no tie-break at a minimum of P.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "attiguard/governor/navigation_field.hpp"
#include "attiguard/governor/saddle_tie_break.hpp"
#include "test_support.hpp"

namespace attiguard::governor {
namespace {

using lie::Mat3;
using lie::Vec3;

constexpr double kTbDeg = std::numbers::pi / 180.0;

Mat3 tb_rot_z(double angle) { return lie::exp(angle * Vec3::UnitZ()); }

/// The symmetric case: star tracker +x, R_d = 120° about z, a 20° keep-out cone around the
/// direction the tracker passes at mid-slew (+x turned 60° about z).
struct SymmetricSunSaddle {
  Mat3 R_d = tb_rot_z(120.0 * kTbDeg);
  std::array<ConeConstraint, 1> cones{
      keep_out_cone(Vec3::UnitX(), tb_rot_z(60.0 * kTbDeg) * Vec3::UnitX(), 20.0 * kTbDeg)};
  /// The equilibrium of ρ_n on the path R_g = Rz(ψ): ρ_n ∥ z there, its z component changes sign.
  [[nodiscard]] double saddle_angle() const {
    double lo = 0.0, hi = 40.0 * kTbDeg;  // attraction wins at lo, the band's barrier at hi
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (lo + hi);
      (navigation_field(cones, tb_rot_z(mid), R_d).z() > 0.0 ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  }
};

TEST(NavigationFieldTieBreak, DetourDirectionIsPerpendicularToTheBodyAxisAndToGc) {
  for (int i = 0; i < 300; ++i) {
    const ConeConstraint cone = keep_in_cone(test::random_unit(), test::random_unit(), 2.0);
    const Mat3 R_g = test::random_rotation();
    const Vec3 h = tie_break_direction(cone, R_g);
    ASSERT_NEAR(h.norm(), 1.0, 1e-12);
    EXPECT_NEAR(h.dot(cone.axis_b), 0.0, 1e-12);
    EXPECT_NEAR(h.dot(constraint_gradient(cone, R_g)), 0.0, 1e-12);
    // Tangent to the level set of c: c is stationary along R_g exp(εĥ).
    const double eps = 1e-6;
    const double dc = (cone_cosine(cone, R_g * lie::exp(eps * h)) - cone_cosine(cone, R_g * lie::exp(-eps * h))) /
                      (2.0 * eps);
    EXPECT_NEAR(dc, 0.0, 1e-8);
  }
  // a_b along a_c: no direction is singled out.
  const ConeConstraint aligned = keep_in_cone(Vec3::UnitX(), Vec3::UnitX(), 1.0);
  EXPECT_TRUE(tie_break_direction(aligned, Mat3::Identity()).isZero());
}

TEST(NavigationFieldTieBreak, SymmetricSaddleIsDetectedAndTheSideIsDeterministic) {
  const SymmetricSunSaddle s;
  const double psi = s.saddle_angle();
  const Mat3 R_g = tb_rot_z(psi);
  // The stall of issue 41: far from R_d, inside the band, attraction and repulsion cancel.
  EXPECT_GT(120.0 * kTbDeg - psi, 80.0 * kTbDeg);
  EXPECT_LT(cone_cosine(s.cones[0], R_g), s.cones[0].zeta);
  const Vec3 rho_n = navigation_field(s.cones, R_g, s.R_d);
  EXPECT_LE(rho_n.norm(), 1e-9);
  const TieBreakUpdate u = update_tie_break(TieBreak{}, s.cones, R_g, s.R_d, 1e-3);
  ASSERT_TRUE(u.started);
  EXPECT_FALSE(u.released);
  EXPECT_TRUE(u.state.active);
  EXPECT_EQ(u.state.cone, 0);
  EXPECT_EQ(u.state.sign, 1.0);  // both sides have the same P: +1
  // Deterministic: the same decision again.
  const TieBreakUpdate again = update_tie_break(TieBreak{}, s.cones, R_g, s.R_d, 1e-3);
  EXPECT_EQ(again.state.cone, u.state.cone);
  EXPECT_EQ(again.state.sign, u.state.sign);
  // ĥ is ±y of the body here (perpendicular to the slew plane's normal z and to a_b = x), and
  // the field with the detour points along σĥ with half the attraction.
  const Vec3 h = tie_break_direction(s.cones[0], R_g);
  EXPECT_NEAR(std::abs(h.y()), 1.0, 1e-12);
  const Vec3 detour = tie_break_field(u.state, s.cones, R_g, s.R_d, rho_n);
  const double attraction = attractive_field(R_g, s.R_d).norm();
  EXPECT_NEAR(detour.dot(h), kTieBreakDetourGain * attraction, 1e-9);
  // Both sides lower P (a saddle): the detour is a descent direction of P to second order.
  const double p = navigation_potential(s.cones, R_g, s.R_d);
  EXPECT_LT(navigation_potential(s.cones, R_g * lie::exp(0.05 * h), s.R_d), p);
  EXPECT_LT(navigation_potential(s.cones, R_g * lie::exp(-0.05 * h), s.R_d), p);
  // Inactive: the field is ρ_n itself.
  EXPECT_EQ(tie_break_field(TieBreak{}, s.cones, R_g, s.R_d, rho_n), rho_n);
}

TEST(NavigationFieldTieBreak, SideIsTheDescentSideOfPAndAClearTangentNeedsNoTieBreak) {
  const SymmetricSunSaddle s;
  const double psi = s.saddle_angle();
  const Mat3 R_g0 = tb_rot_z(psi);
  const Vec3 h0 = tie_break_direction(s.cones[0], R_g0);
  for (const double side : {-1.0, 1.0}) {
    // Slightly off the symmetric plane: P is lower on that side, the tie-break takes it.
    const Mat3 near = R_g0 * lie::exp(side * 2e-4 * h0);
    const Vec3 h = tie_break_direction(s.cones[0], near);
    const double attraction = attractive_field(near, s.R_d).norm();
    ASSERT_LE(std::abs(navigation_field(s.cones, near, s.R_d).dot(h)), kTieBreakClearTangent * attraction);
    const TieBreakUpdate u = update_tie_break(TieBreak{}, s.cones, near, s.R_d, 1e-3);
    ASSERT_TRUE(u.started);
    EXPECT_EQ(u.state.sign * h.dot(h0) > 0.0 ? 1.0 : -1.0, side);
    // Farther off: the field's own tangential component takes R_g around, no tie-break.
    const Mat3 off = R_g0 * lie::exp(side * 0.05 * h0);
    ASSERT_GT(std::abs(navigation_field(s.cones, off, s.R_d).dot(tie_break_direction(s.cones[0], off))),
              kTieBreakClearTangent * attractive_field(off, s.R_d).norm());
    EXPECT_FALSE(update_tie_break(TieBreak{}, s.cones, off, s.R_d, 1e-3).started);
  }
}

TEST(NavigationFieldTieBreak, SideAvoidsAnotherConesBandMetAroundTheCone) {
  // The symmetric saddle with a second keep-out cone 50° above the Sun (its band overlaps the
  // Sun's above it): the look-ahead a quarter turn around the Sun's cone picks the side below.
  for (const double elevation : {50.0, -50.0}) {
    SymmetricSunSaddle s;
    const double psi = s.saddle_angle();
    const double e = elevation * kTbDeg;
    const std::array<ConeConstraint, 2> cones{
        s.cones[0], keep_out_cone(Vec3::UnitX(), tb_rot_z(60.0 * kTbDeg) * Vec3(std::cos(e), 0.0, std::sin(e)),
                                  15.0 * kTbDeg)};
    const Mat3 R_g = tb_rot_z(psi);
    ASSERT_LE(navigation_field(cones, R_g, s.R_d).norm(), 1e-9);  // the second band is far from the saddle
    const TieBreakUpdate u = update_tie_break(TieBreak{}, cones, R_g, s.R_d, 1e-3);
    ASSERT_TRUE(u.started);
    EXPECT_EQ(u.state.cone, 0);
    // The body axis moves away from the second cone: down when it is above, up when below.
    const Mat3 moved = R_g * lie::exp(u.state.sign * 0.05 * tie_break_direction(cones[0], R_g));
    EXPECT_LT((moved * Vec3::UnitX()).z() * elevation, 0.0) << elevation;
  }
}

TEST(NavigationFieldTieBreak, NoDetectionWithoutAnActiveBandABalancedFieldOrDistanceToRd) {
  const SymmetricSunSaddle s;
  // Band inactive (ψ = 10°: the tracker 50° from the Sun): ρ_n = ρ_a.
  EXPECT_FALSE(update_tie_break(TieBreak{}, s.cones, tb_rot_z(10.0 * kTbDeg), s.R_d, 1e-3).started);
  // In the band but not balanced: just inside ζ the repulsion is tiny.
  double psi = 0.0;
  while (cone_cosine(s.cones[0], tb_rot_z(psi)) >= s.cones[0].zeta) psi += 1e-4;
  const Mat3 R_g = tb_rot_z(psi);
  ASSERT_GT(navigation_field(s.cones, R_g, s.R_d).norm(), kTieBreakBalance * attractive_field(R_g, s.R_d).norm());
  EXPECT_FALSE(update_tie_break(TieBreak{}, s.cones, R_g, s.R_d, 1e-3).started);
  // At R_d: nothing to break.
  EXPECT_FALSE(update_tie_break(TieBreak{}, s.cones, s.R_d, s.R_d, 1e-3).started);
  // No cones: nothing to break either.
  EXPECT_FALSE(update_tie_break(TieBreak{}, {}, tb_rot_z(0.3), s.R_d, 1e-3).started);
}

TEST(NavigationFieldTieBreak, ReleasedWhenTheFieldTakesOverOrTheBandIsLeft) {
  const SymmetricSunSaddle s;
  const double psi = s.saddle_angle();
  const TieBreak held{true, 0, 1.0};
  // Still at the saddle: held.
  const TieBreakUpdate kept = update_tie_break(held, s.cones, tb_rot_z(psi), s.R_d, 1e-3);
  EXPECT_TRUE(kept.state.active);
  EXPECT_FALSE(kept.released);
  EXPECT_FALSE(kept.started);
  // Well off the plane on the held side: the natural field's component along σĥ is large.
  const Mat3 R_g = tb_rot_z(psi) * lie::exp(0.3 * tie_break_direction(s.cones[0], tb_rot_z(psi)));
  ASSERT_GE(navigation_field(s.cones, R_g, s.R_d).dot(tie_break_direction(s.cones[0], R_g)),
            kTieBreakRelease * attractive_field(R_g, s.R_d).norm());
  const TieBreakUpdate off = update_tie_break(held, s.cones, R_g, s.R_d, 1e-3);
  EXPECT_TRUE(off.released);
  EXPECT_FALSE(off.state.active);
  // Out of the band: released.
  EXPECT_TRUE(update_tie_break(held, s.cones, tb_rot_z(10.0 * kTbDeg), s.R_d, 1e-3).released);
}

TEST(NavigationFieldTieBreak, AMinimumOfPIsNotBroken) {
  // A keep-in cone (the body axis must stay within 40° of +x) with R_d outside reach in the
  // direction of the slew: along the geodesic the band holds R_g at a minimum of P, and moving
  // sideways along ĥ leaves c at the first order but lowers it at the second: P rises on both
  // sides, the stall is real.
  const std::array<ConeConstraint, 1> cones{keep_in_cone(Vec3::UnitX(), Vec3::UnitX(), 40.0 * kTbDeg)};
  const Mat3 R_d = tb_rot_z(90.0 * kTbDeg);
  double lo = 0.0, hi = 40.0 * kTbDeg;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (navigation_field(cones, tb_rot_z(mid), R_d).z() > 0.0 ? lo : hi) = mid;
  }
  const Mat3 R_g = tb_rot_z(0.5 * (lo + hi));
  ASSERT_LT(cone_cosine(cones[0], R_g), cones[0].zeta);
  ASSERT_LE(navigation_field(cones, R_g, R_d).norm(), 1e-9);
  EXPECT_FALSE(update_tie_break(TieBreak{}, cones, R_g, R_d, 1e-3).started);
}

}  // namespace
}  // namespace attiguard::governor
