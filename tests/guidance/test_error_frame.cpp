// Error frame (6)-(12) and velocity-projection frame (17)-(22) of the waypoint paper: geometry,
// errata (8)/(9)/(18), singular configurations.
#include <gtest/gtest.h>

#include <cmath>

#include "attiguard/guidance/desired_attitude.hpp"
#include "attiguard/lie/quaternion.hpp"
#include "attiguard/lie/shortest_arc.hpp"
#include "test_support.hpp"

namespace attiguard::guidance {
namespace {

using lie::Quat;

Quat random_quat() { return lie::rotation_to_quat(test::random_rotation()); }

/// Body rate of q(t) by central differences: ω = 2 vec(q* ⊗ q̇).
Vec3 fd_rate(const Quat& q_minus, const Quat& q, const Quat& q_plus, double h) {
  Quat qp = q_plus;
  Quat qm = q_minus;
  if (qp.dot(q) < 0) qp = -qp;
  if (qm.dot(q) < 0) qm = -qm;
  const Quat q_dot = (qp - qm) / (2.0 * h);
  return 2.0 * lie::quat_multiply(lie::quat_conjugate(q), q_dot).tail<3>();
}

TEST(ErrorFrame, MapsBodyXOntoTheErrorDirection) {
  for (int k = 0; k < 2000; ++k) {
    const Vec3 e_i = test::random_vector_in_ball(1e4);
    // Paper chart (identity) and random charts; ϑ < π.
    const Quat chart = k % 2 == 0 ? lie::quat_identity() : random_quat();
    if ((lie::quat_to_rotation(chart).col(0)).dot(e_i.normalized()) < -0.999) continue;
    const ErrorFrame f = error_frame(chart, e_i, Vec3::Zero());
    const Vec3 x_i = lie::quat_to_rotation(f.q_ie) * Vec3::UnitX();
    EXPECT_LT((x_i - e_i.normalized()).norm(), 1e-12);
    EXPECT_NEAR(f.q_ie.norm(), 1.0, 1e-14);
    // R_i^e e^i = e^e = [‖e‖, 0, 0] (7).
    const Vec3 e_e = lie::quat_to_rotation(f.q_ie).transpose() * e_i;
    EXPECT_LT((e_e - Vec3(e_i.norm(), 0, 0)).norm(), 1e-9 * e_i.norm());
  }
}

TEST(ErrorFrame, Erratum8PrintedQuaternionRotatesByPiMinusTheta) {
  // As printed, [sin(ϑ/2), k cos(ϑ/2)] rotates x by π − ϑ, not onto ê.
  for (double theta_deg : {10.0, 45.0, 80.0, 120.0, 170.0}) {
    const double th = theta_deg * M_PI / 180.0;
    const Vec3 e_i(std::cos(th), std::sin(th) * 0.6, std::sin(th) * 0.8);
    const Vec3 x_printed = lie::quat_to_rotation(eq8_as_printed(e_i)) * Vec3::UnitX();
    EXPECT_NEAR(std::acos(std::clamp(x_printed.x(), -1.0, 1.0)), M_PI - th, 1e-9);
    const Vec3 x_fixed = lie::quat_to_rotation(error_frame(lie::quat_identity(), e_i, Vec3::Zero()).q_ie) *
                         Vec3::UnitX();
    EXPECT_LT((x_fixed - e_i.normalized()).norm(), 1e-12);
  }
}

TEST(ErrorFrame, Erratum9PrintedRateIsZeroAndCorrectedRateMissesTheTwist) {
  for (int k = 0; k < 500; ++k) {
    const Quat chart = random_quat();
    Vec3 e_i = test::random_vector_in_ball(500.0);
    if ((lie::quat_to_rotation(chart).col(0)).dot(e_i.normalized()) < -0.5) e_i = -e_i;
    const Vec3 v_i = test::random_vector_in_ball(10.0);
    const ErrorFrame f = error_frame(chart, e_i, -v_i);
    // (9) as printed is identically zero.
    EXPECT_LT(eq9_as_printed(f.q_ie, e_i).norm(), 1e-14);
    // (9) with ė = −v is the component of the true rate perpendicular to x_e ...
    const Vec3 w9 = eq9_corrected_rate(f.q_ie, e_i, -v_i);
    const Vec3 diff = f.omega_e - w9;
    EXPECT_LT(std::hypot(diff.y(), diff.z()), 1e-12 * (1.0 + f.omega_e.norm()));
    // ... and exact when the chart x axis lies along ê (ϑ = 0).
    const ErrorFrame f0 = error_frame(f.q_ie, e_i, -v_i);
    EXPECT_LT((f0.omega_e - eq9_corrected_rate(f0.q_ie, e_i, -v_i)).norm(), 1e-12);
  }
}

TEST(ErrorFrame, RateMatchesFiniteDifferencesIncludingNearParallelAndAntiParallel) {
  const double h = 1e-5;
  const Vec3 p_wp(1000.0, 0.0, 0.0);
  for (double angle_deg : {0.0, 1e-6, 1e-3, 30.0, 90.0, 150.0, 179.0, 179.9}) {
    // Chart = identity (the paper's construction), ê at the given angle from x.
    const double a = angle_deg * M_PI / 180.0;
    const Vec3 e0 = 800.0 * Vec3(std::cos(a), std::sin(a), 0.0);
    const Vec3 p = p_wp - e0;
    const Vec3 v(3.0, -2.0, 1.5);
    auto q_at = [&](double t) { return error_frame(lie::quat_identity(), p_wp - (p + v * t), -v).q_ie; };
    const ErrorFrame f = error_frame(lie::quat_identity(), p_wp - p, -v);
    const Vec3 w_fd = fd_rate(q_at(-h), q_at(0.0), q_at(h), h);
    EXPECT_TRUE(f.omega_e.allFinite());
    EXPECT_LT((f.omega_e - w_fd).norm(), 1e-5 * w_fd.norm()) << "angle " << angle_deg;
  }
}

TEST(ErrorFrame, ZeroAndTinyErrorStayFinite) {
  const Quat chart = random_quat();
  const ErrorFrame z = error_frame(chart, Vec3::Zero(), Vec3(1, 2, 3));
  EXPECT_TRUE(z.q_ie.isApprox(chart));
  EXPECT_TRUE(z.omega_e.isZero());
  const ErrorFrame t = error_frame(chart, lie::quat_to_rotation(chart).col(0) * 1e-300, Vec3(1, 2, 3));
  EXPECT_TRUE(t.q_ie.allFinite());
  EXPECT_TRUE(t.omega_e.allFinite());
  EXPECT_LT(t.omega_e.norm(), 1e7);  // bounded by ‖v‖/e_floor
}

TEST(VelocityFrame, FullProjectionPointsTheThrustAgainstTheVelocity) {
  GuidanceFrameSpec spec;
  spec.error_sign = -1.0;  // reversed error vector (Fig. 1(b))
  spec.projection = true;
  const Vec3 p_wp(0, 0, 0);
  for (int k = 0; k < 500; ++k) {
    const Vec3 p = test::random_vector_in_ball(1e4);
    // Velocity toward the waypoint within 60° of it.
    Vec3 v = -p.normalized() * 50.0 + test::random_vector_in_ball(20.0);
    if (v.normalized().dot(-p.normalized()) < 0.5) continue;
    spec.q_ir = lie::shortest_arc_quat(Vec3::UnitX(), p - p_wp);
    const DesiredAttitude d = desired_attitude(spec, p_wp, p, v, Vec3::Zero());
    EXPECT_DOUBLE_EQ(d.velocity.weight, 1.0);
    const Vec3 x_d = lie::quat_to_rotation(d.q_id).col(0);
    EXPECT_LT((x_d + v.normalized()).norm(), 1e-12);  // v^d = [−‖v‖, 0, 0] (17)
  }
}

TEST(VelocityFrame, RateMatchesFiniteDifferencesInEveryRegime) {
  // Regimes: full projection, speed blend (‖v‖ < v_blend), angle blend (∠ near 89-90°),
  // suppressed (∠ > 90°, v = 0), w nearly parallel to x_e.
  GuidanceFrameSpec spec;
  spec.error_sign = -1.0;
  spec.projection = true;
  spec.projection_params.cos_full = 0.5;  // a wide angle band so it is sampled below
  const Vec3 p_wp(0, 0, 0);
  const double h = 1e-6;
  int checked = 0;
  for (int k = 0; k < 3000; ++k) {
    const Vec3 p = test::random_vector_in_ball(300.0);
    const double speed_scale = (k % 3 == 0) ? 0.08 : 30.0;
    const Vec3 v = test::random_vector_in_ball(speed_scale);
    const Vec3 a = test::random_vector_in_ball(0.3);
    spec.q_ir = lie::shortest_arc_quat(Vec3::UnitX(), (p - p_wp) + test::random_vector_in_ball(0.5 * p.norm()));
    auto at = [&](double t) {
      return desired_attitude(spec, p_wp, p + v * t + 0.5 * a * t * t, v + a * t, a);
    };
    const DesiredAttitude d0 = at(0.0);
    const DesiredAttitude dm = at(-h);
    const DesiredAttitude dp = at(h);
    ASSERT_TRUE(d0.q_id.allFinite());
    ASSERT_TRUE(d0.omega_d.allFinite());
    const Vec3 w_ed = fd_rate(dm.velocity.q_ed, d0.velocity.q_ed, dp.velocity.q_ed, h);
    const Vec3 w_id = fd_rate(dm.q_id, d0.q_id, dp.q_id, h);
    EXPECT_LE((d0.velocity.omega_d - w_ed).norm(), 1e-5 * std::max(w_ed.norm(), 1e-4));
    EXPECT_LE((d0.omega_d - w_id).norm(), 1e-5 * std::max(w_id.norm(), 1e-4));
    ++checked;
  }
  EXPECT_GT(checked, 2000);
}

TEST(VelocityFrame, ContinuousAcrossTheBlendBoundariesAndFiniteAtSingularities) {
  VelocityProjectionParams params;
  const Quat q_ie = lie::quat_identity();
  // Sweep the velocity direction through 180° (antiparallel to the sign-adjusted x) and its
  // magnitude through 0: the frame moves continuously and stays finite.
  Quat prev = velocity_frame(q_ie, Vec3::Zero(), Vec3(-1, 0, 0), Vec3::Zero(), -1.0, params).q_ed;
  for (int i = 1; i <= 20000; ++i) {
    const double a = M_PI * i / 20000.0;
    const Vec3 v = -Vec3(std::cos(a), std::sin(a), 0.0);
    const VelocityFrame f = velocity_frame(q_ie, Vec3(0, 0, 0.1), v, Vec3(0.1, 0.2, 0), -1.0, params);
    ASSERT_TRUE(f.q_ed.allFinite() && f.omega_d.allFinite());
    // Lipschitz in the direction: the steepest part is the 89°-90° fade band (slope ≈ 89°/1°/2).
    EXPECT_LT((f.q_ed - prev).norm(), 100.0 * M_PI / 20000.0);
    prev = f.q_ed;
  }
  const VelocityFrame zero = velocity_frame(q_ie, Vec3::Zero(), Vec3::Zero(), Vec3(1, 0, 0), -1.0, params);
  EXPECT_EQ(zero.weight, 0.0);
  EXPECT_TRUE(zero.q_ed.isApprox(lie::quat_identity()));
  const VelocityFrame anti = velocity_frame(q_ie, Vec3::Zero(), Vec3(5, 0, 0), Vec3::Zero(), -1.0, params);
  EXPECT_EQ(anti.weight, 0.0);  // w antiparallel to x_e: projection suppressed, no singular axis
}

// Issue 13: crossing a waypoint in a straight line makes ê exactly antiparallel to the chart's x
// axis (n = 0 in the unnormalised form): the frame was NaN and the integrator diverged. It is
// now the half turn about the chart's z axis, finite, mapping x_b onto ê.
TEST(ErrorFrame, ExactlyAntiparallelToTheChartStaysFinite) {
  const Quat q_ir = lie::quat_identity();
  for (const Vec3& e_dot : {Vec3(1.0, 0.0, 0.0), Vec3(0.3, -0.2, 0.1), Vec3(0.0, 0.0, 0.0)}) {
    const ErrorFrame f = error_frame(q_ir, Vec3(-2.0, 0.0, 0.0), e_dot);
    ASSERT_TRUE(f.q_ie.allFinite() && f.omega_e.allFinite());
    EXPECT_NEAR(f.q_ie.norm(), 1.0, 1e-15);
    EXPECT_TRUE(lie::quat_to_rotation(f.q_ie).col(0).isApprox(Vec3(-1.0, 0.0, 0.0), 1e-15));
    EXPECT_LT(f.cos_chart, -1.0 + 1e-15);
  }
}

}  // namespace
}  // namespace attiguard::guidance
