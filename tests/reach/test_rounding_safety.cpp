// Rounding sites of the safety check (docs/reach.md, "Rounding sites"): constructed cases at the
// edge where the round-to-nearest check of before (acos of a rounded normalised dot product, the
// float centre taken as a rotation, a round-to-nearest ‖ω‖) proves a constraint that the exact
// numbers violate; the outward-rounded check refuses them and still accepts comfortable margins.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <random>

#include "attiguard/lie/so3.hpp"
#include "attiguard/reach/safety.hpp"

namespace ar = attiguard::reach;

namespace rounding_safety_test {

/// The check of before (safety.cpp until issue 47): acos of the rounded normalised dot product.
double float_angle(const ar::Vec3& a, const ar::Vec3& b) {
  return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0));
}
bool float_cone_ok(const ar::PointingCone& c, const ar::AttitudeBall& att) {
  const double phi = float_angle(att.center * c.axis_b, c.direction_i);
  return c.keep_out ? (phi - att.radius > c.half_angle) : (phi + att.radius < c.half_angle);
}

ar::TubeSegment segment(const ar::Mat3& Rc, double rho) {
  ar::TubeSegment seg;
  seg.t0 = 0.0;
  seg.t1 = 0.1;
  seg.attitude = {Rc, rho};
  return seg;
}

ar::SafetySpec cone_spec(const ar::Vec3& a, const ar::Vec3& d, double alpha, bool keep_out) {
  ar::SafetySpec spec;
  spec.cones.push_back({"edge", a, d, alpha, keep_out});
  return spec;
}

/// a = e_x and d = (1, t, 0): the exact angle is atan(t) (the C library's atan within 1 ulp,
/// ~2e-22 here). The first t = k 2⁻²⁰ whose rounded-dot angle is off by more than 1e-15 in the
/// requested direction (over: the float angle is larger than the truth).
std::optional<double> edge_t(bool over) {
  const ar::Vec3 a(1.0, 0.0, 0.0);
  for (int k = 1; k < 4000; ++k) {
    const double t = std::ldexp(static_cast<double>(k), -20);
    const double err = float_angle(a, ar::Vec3(1.0, t, 0.0)) - std::atan(t);
    if (over ? err > 1e-15 : err < -1e-15) return t;
  }
  return std::nullopt;
}

/// The cone at the edge of the float angle: d = (1, t, 0), a = e_x, θ = atan(t) the true angle,
/// φ the round-to-nearest one (on the side `over` of θ), α halfway between them.
struct EdgeCone {
  ar::Vec3 a{1.0, 0.0, 0.0};
  ar::Vec3 d;
  double theta{0.0};
  double phi_float{0.0};
  double alpha{0.0};
};

std::optional<EdgeCone> edge_cone(bool over) {
  const std::optional<double> t = edge_t(over);
  if (!t) return std::nullopt;
  EdgeCone c;
  c.d = ar::Vec3(1.0, *t, 0.0);
  c.theta = std::atan(*t);
  c.phi_float = float_angle(c.a, c.d);
  c.alpha = 0.5 * (c.theta + c.phi_float);
  return c;
}

}  // namespace rounding_safety_test

namespace rst = rounding_safety_test;

TEST(RoundingSafety, KeepOutConeTheRoundedAcosWouldProveIsRefused) {
  // rounding site: cone-angle. The true angle θ = atan(t) is below α, α below the float angle:
  // the keep-out constraint angle ≥ α is violated (ρ = 0: the ball is the point R = I).
  const std::optional<rst::EdgeCone> c = rst::edge_cone(true);
  ASSERT_TRUE(c.has_value());
  const auto& [a, d, theta, phi_float, alpha] = *c;
  ASSERT_LT(theta, alpha);
  ASSERT_LT(alpha, phi_float);
  const ar::SafetySpec spec = rst::cone_spec(a, d, alpha, true);
  const ar::TubeSegment seg = rst::segment(ar::Mat3::Identity(), 0.0);
  EXPECT_TRUE(rst::float_cone_ok(spec.cones.front(), seg.attitude));  // round-to-nearest: "safe"
  EXPECT_FALSE(ar::violated_by_segment(spec, seg).empty());
  // A comfortable margin is still proved: α = θ/2, ρ = θ/4.
  EXPECT_TRUE(ar::violated_by_segment(rst::cone_spec(a, d, 0.5 * theta, true), rst::segment(ar::Mat3::Identity(), 0.25 * theta)).empty());
}

TEST(RoundingSafety, KeepInConeTheRoundedAcosWouldProveIsRefused) {
  // rounding site: cone-angle. The float angle is below α, the true angle above it: the keep-in
  // constraint angle ≤ α is violated.
  const std::optional<rst::EdgeCone> c = rst::edge_cone(false);
  ASSERT_TRUE(c.has_value());
  const auto& [a, d, theta, phi_float, alpha] = *c;
  ASSERT_LT(phi_float, alpha);
  ASSERT_LT(alpha, theta);
  const ar::SafetySpec spec = rst::cone_spec(a, d, alpha, false);
  const ar::TubeSegment seg = rst::segment(ar::Mat3::Identity(), 0.0);
  EXPECT_TRUE(rst::float_cone_ok(spec.cones.front(), seg.attitude));
  EXPECT_FALSE(ar::violated_by_segment(spec, seg).empty());
  EXPECT_TRUE(ar::violated_by_segment(rst::cone_spec(a, d, 2.0 * theta, false), rst::segment(ar::Mat3::Identity(), 0.5 * theta)).empty());
}

TEST(RoundingSafety, ANonOrthogonalCentreIsReadThroughItsPolarFactor) {
  // rounding site: cone-angle (centre defect). R_c = I + δ e_y e_xᵀ (a shear) is not a rotation:
  // R_c e_x is at the angle atan(δ) from e_x, but its polar factor, the rotation the ball is
  // centred on, is the rotation by atan(δ/2) about z. Keep-out α = 0.75 δ: violated by the
  // rotation, "safe" for the float centre taken as one.
  const double delta = std::ldexp(1.0, -20);
  ar::Mat3 Rc = ar::Mat3::Identity();
  Rc(1, 0) = delta;
  const ar::Vec3 a(1.0, 0.0, 0.0);
  const ar::Vec3 d(1.0, 0.0, 0.0);
  ASSERT_LT(std::atan(0.5 * delta), 0.75 * delta);  // the polar factor's axis is inside the cone
  const ar::SafetySpec spec = rst::cone_spec(a, d, 0.75 * delta, true);
  const ar::TubeSegment seg = rst::segment(Rc, 0.0);
  EXPECT_TRUE(rst::float_cone_ok(spec.cones.front(), seg.attitude));
  EXPECT_FALSE(ar::violated_by_segment(spec, seg).empty());
  // A float rotation (defect ~1e-16) with a comfortable margin: proved.
  std::mt19937_64 g(47);
  std::normal_distribution<double> n(0.0, 1.0);
  for (int k = 0; k < 20; ++k) {
    const ar::Mat3 R = attiguard::lie::exp(ar::Vec3(n(g), n(g), n(g)));
    const ar::Vec3 axis = ar::Vec3(n(g), n(g), n(g)).normalized();
    const ar::Vec3 dir = ar::Vec3(n(g), n(g), n(g)).normalized();
    const double phi = rst::float_angle(R * axis, dir);
    if (phi < 0.2 || phi > 2.9) continue;
    EXPECT_TRUE(ar::violated_by_segment(rst::cone_spec(axis, dir, phi - 0.1, true), rst::segment(R, 0.05)).empty());
    EXPECT_TRUE(ar::violated_by_segment(rst::cone_spec(axis, dir, phi + 0.1, false), rst::segment(R, 0.05)).empty());
  }
}

TEST(RoundingSafety, OmegaNormBoundTheRoundedNormWouldProveIsRefused) {
  // rounding site: omega-norm-check. Pythagorean quadruples (Lebesgue's identity):
  // (m²+n²−p²−q²)² + (2(mq+np))² + (2(nq−mp))² = (m²+n²+p²+q²)², all below 2⁵³ (exact doubles),
  // their squares not. ω = (x, y, z) has ‖ω‖ = N exactly, so ‖ω‖ < N is violated; find one whose
  // round-to-nearest norm is below N.
  std::optional<ar::Vec3> w;
  double N = 0.0;
  for (std::int64_t m = (1 << 20) + 1; m < (1 << 20) + 60 && !w; ++m) {
    for (std::int64_t q = 1000; q < 1060 && !w; ++q) {
      const std::int64_t nn = 777'777, p = 123'457;
      const std::int64_t x = m * m + nn * nn - p * p - q * q;
      const std::int64_t y = 2 * (m * q + nn * p);
      const std::int64_t z = 2 * (nn * q - m * p);
      const std::int64_t s = m * m + nn * nn + p * p + q * q;
      ASSERT_LT(s, std::int64_t{1} << 53);
      const ar::Vec3 v(static_cast<double>(x), static_cast<double>(y), static_cast<double>(z));
      const ar::Box3 box{v, v};
      if (box.norm_max() < static_cast<double>(s)) {
        w = v;
        N = static_cast<double>(s);
      }
    }
  }
  ASSERT_TRUE(w.has_value());
  ar::SafetySpec spec;
  spec.omega_norm_max = N;
  ar::TubeSegment seg = rst::segment(ar::Mat3::Identity(), 0.0);
  seg.omega = ar::Box3{*w, *w};
  EXPECT_LT(seg.omega.norm_max(), N);  // round-to-nearest: "safe"
  EXPECT_EQ(ar::violated_by_segment(spec, seg), "omega_norm_max");
  spec.omega_norm_max = N * (1.0 + 1e-12);
  EXPECT_TRUE(ar::violated_by_segment(spec, seg).empty());
}
