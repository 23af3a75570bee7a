// Quaternion PID (25)-(27), RCT law (28) and allocation (29)-(30) of the waypoint paper.
#include <gtest/gtest.h>

#include <cmath>
#include <exception>
#include <vector>

#include "attiguard/control/quaternion_pid.hpp"
#include "attiguard/control/rct_allocation.hpp"
#include "attiguard/control/rct_position_law.hpp"
#include "attiguard/dynamics/spacecraft_plant.hpp"
#include "attiguard/integrate/integrator.hpp"
#include "test_support.hpp"

namespace attiguard::control {
namespace {

using lie::Quat;
using lie::Vec3;

TEST(RctAllocation, ReproducesEveryForceWithinTheLimits) {
  const double f_max = 0.5;
  for (int k = 0; k < 10000; ++k) {
    Vec3 f = test::random_vector_in_ball(1.0);
    f = f.cwiseMax(-f_max).cwiseMin(f_max);  // each axis within what one thruster can give
    const RctVector T = rct_allocate(f);
    EXPECT_LT((rct_body_force(T) - f).norm(), 1e-15);
    EXPECT_GE(T.minCoeff(), 0.0);
    EXPECT_LE(T.maxCoeff(), f_max);
    // It is B† f (29) plus a null-space component of B (30).
    EXPECT_LT((rct_allocation_matrix() * (T - rct_pseudo_inverse(f))).norm(), 1e-15);
  }
  // The pure pseudo-inverse (29) asks for negative (pulling) thrust on every axis.
  EXPECT_LT(rct_pseudo_inverse(Vec3(0.3, -0.2, 0.1)).minCoeff(), 0.0);
  EXPECT_LT((rct_allocation_matrix() * rct_pseudo_inverse(Vec3(0.3, -0.2, 0.1)) - Vec3(0.3, -0.2, 0.1)).norm(), 1e-15);
}

TEST(RctAllocation, BangBangFiresTheThrusterOnTheRightSide) {
  for (int k = 0; k < 1000; ++k) {
    const Vec3 f = test::random_vector_in_ball(2.0);
    const RctVector on = rct_bang_bang(rct_allocate(f), 0.5, 0.5);
    const Vec3 F = rct_body_force(on);
    for (int i = 0; i < 3; ++i) {
      if (std::abs(f(i)) >= 0.25) {
        EXPECT_EQ(F(i), std::copysign(0.5, f(i)));
      } else {
        EXPECT_EQ(F(i), 0.0);
      }
      EXPECT_EQ(on(2 * i) * on(2 * i + 1), 0.0);  // never both of a pair
    }
  }
}

/// 1-D double integrator under (28) with κ_p of the given sign convention, from e0 = 10 m.
double final_error(double kappa_p_sign) {
  const double m = 100.0, kp = 0.02, kd = 0.5;
  double p = 0.0, v = 0.0;
  const double p_wp = 10.0;
  for (int k = 0; k < 20000; ++k) {  // 2000 s at 0.1 s
    const double e = p_wp - p;
    const double f = m * (kappa_p_sign * kp * e - kd * v);
    v += f / m * 0.1;
    p += v * 0.1;
  }
  return std::abs(p_wp - p);
}

TEST(RctPositionLaw, Erratum28PrintedSignDivergesCorrectedSignConverges) {
  EXPECT_LT(final_error(+1.0), 1e-6);  // implemented: f = m R_i^b (κ_p e − κ_d v)
  EXPECT_GT(final_error(-1.0), 1e6);   // printed: f = m R_i^b (−κ_p e − κ_d v) pushes away
  // And the implementation is the +κ_p one, expressed in body axes.
  const lie::Mat3 R = test::random_rotation();
  const Vec3 e(1, 2, 3), v(0.1, -0.2, 0.3);
  const Vec3 f_b = rct_position_force(100.0, R, e, v, {0.02, 0.5});
  EXPECT_LT((R * f_b - 100.0 * (0.02 * e - 0.5 * v)).norm(), 1e-12);
}

// Issue 42: the lateral RCT force damps the speed across the line of sight only: perpendicular
// to e, −m k v_⊥ in inertial axes, zero for motion along e or at e = 0.
TEST(RctPositionLaw, LateralForceDampsOnlyTheSpeedAcrossTheLineOfSight) {
  const lie::Mat3 R = test::random_rotation();
  const Vec3 e(30.0, -10.0, 5.0);
  const Vec3 v(0.4, 0.3, -0.2);
  const Vec3 f_i = R * rct_lateral_force(50.0, R, e, v, 0.7);
  EXPECT_LT(std::abs(f_i.dot(e)), 1e-12 * f_i.norm() * e.norm());
  const Vec3 v_perp = v - e * (e.dot(v) / e.squaredNorm());
  EXPECT_LT((f_i + 50.0 * 0.7 * v_perp).norm(), 1e-12 * f_i.norm());
  EXPECT_LT(rct_lateral_force(50.0, R, e, 2.5 * e, 0.7).norm(), 1e-12);
  EXPECT_EQ(rct_lateral_force(50.0, R, Vec3::Zero(), v, 0.7), Vec3::Zero());
}

// Issue 25: far from the waypoint the position term asks for the braking curve's speed
// √(2 b ‖e‖) instead of the switching line's λ‖e‖; inside 2b/λ² it is (28) unchanged.
TEST(RctPositionLaw, BrakingCurveCapsTheApproachSpeedFarFromTheWaypoint) {
  const RctPositionGains line{0.02, 0.5};
  RctPositionGains curve = line;
  curve.braking_acceleration = 0.001;  // 2b/λ² = 1.25 m with λ = 0.04 1/s
  const lie::Mat3 R = test::random_rotation();
  const Vec3 dir = Vec3(1.0, -2.0, 0.5).normalized();
  const Vec3 v(0.01, 0.0, -0.02);
  for (double d : {0.1, 0.5, 1.2}) {  // inside: identical
    EXPECT_LT((rct_position_force(100.0, R, dir * d, v, curve) - rct_position_force(100.0, R, dir * d, v, line)).norm(), 1e-12);
  }
  for (double d : {2.0, 50.0, 5000.0}) {  // outside: κ_d (√(2 b d) ê − v)
    const Vec3 expected = 100.0 * 0.5 * (std::sqrt(2.0 * 0.001 * d) * dir - v);
    EXPECT_LT((R * rct_position_force(100.0, R, dir * d, v, curve) - expected).norm(), 1e-9 * expected.norm()) << d;
  }
}

TEST(QuaternionPid, ErrorKinematicsMatchFiniteDifferences) {
  // ε̇ of (26) against the derivative of ε(q_{d,b}(t)) for a body and a desired frame both
  // rotating at constant rates.
  const double h = 1e-6;
  for (int k = 0; k < 200; ++k) {
    const Quat q_ib0 = lie::rotation_to_quat(test::random_rotation());
    const Quat q_id0 = lie::rotation_to_quat(test::random_rotation());
    const Vec3 w_b = test::random_vector_in_ball(1.0);
    const Vec3 w_d = test::random_vector_in_ball(1.0);
    auto eps_at = [&](double t) {
      const Quat q_ib = lie::quat_multiply(q_ib0, lie::quat_from_rotation_vector(w_b * t));
      const Quat q_id = lie::quat_multiply(q_id0, lie::quat_from_rotation_vector(w_d * t));
      return Vec3(attitude_error(q_id, q_ib).tail<3>());
    };
    QuaternionPid pid({20.0, 0.0, 20.0});
    const QuaternionPidOutput out = pid.step(q_ib0, w_b, q_id0, w_d, 0.1);
    const Vec3 fd = (eps_at(h) - eps_at(-h)) / (2 * h);
    EXPECT_LT((out.eps_dot - fd).norm(), 1e-7);
  }
}

TEST(QuaternionPid, Erratum25PrintedErrorIsTheIdentity) {
  const Quat q_id = lie::rotation_to_quat(test::random_rotation());
  const Quat printed = lie::quat_multiply(lie::quat_conjugate(q_id), q_id);  // q_{d,i} ⊗ q_{i,d}
  EXPECT_LT((printed - lie::quat_identity()).norm(), 1e-15);
}

TEST(QuaternionPid, TableIGainsConvergeToAFixedAttitude) {
  // Plant (4)-(5) with J = 20 I under the sampled PID (27) with the gains of Table I.
  const dynamics::SpacecraftPlant plant(100.0, lie::Mat3::Identity() * 20.0);
  for (int trial = 0; trial < 20; ++trial) {
    dynamics::SpacecraftState y;
    y.R[0] = test::random_rotation();
    y.x.segment<3>(0) = test::random_vector_in_ball(0.2);
    const Quat q_id = lie::rotation_to_quat(test::random_rotation());
    Quat q_ib = lie::rotation_to_quat(y.R[0]);
    if (attitude_error(q_id, q_ib)(0) < 0) q_ib = -q_ib;
    QuaternionPid pid({20.0, 2.0, 20.0});
    dynamics::SpacecraftInputs u;
    std::vector<double> stops;
    for (int k = 1; k <= 3000; ++k) stops.push_back(0.1 * k);
    auto sample = [&](double, const dynamics::SpacecraftState& s) {
      const Quat q = lie::rotation_to_quat(s.R[0]);
      q_ib = q.dot(q_ib) < 0 ? Quat(-q) : q;
      u.tau_b = pid.step(q_ib, dynamics::omega_b_of(s), q_id, Vec3::Zero(), 0.1).tau_b;
    };
    sample(0.0, y);
    integrate::IntegratorSettings settings;
    settings.step = 0.1;
    (void)integrate::integrate(
        [&](double, const dynamics::SpacecraftState& s) { return plant.derivative(s, u); }, y, 0.0,
        std::span<const double>(stops), settings,
        [&](double t, dynamics::SpacecraftState& s) { sample(t, s); return true; },
        [](double, const dynamics::SpacecraftState&) {});
    EXPECT_LT(attitude_error(q_id, q_ib).tail<3>().norm(), 1e-6);
  }
}

/// Closed loop of the plant (4)-(5) with inertia J under `pid` sampled at 10 Hz for `seconds`:
/// the final ‖ε‖ (NaN/inf if it diverged).
double final_error(const lie::Mat3& J, QuaternionPid pid, double seconds) {
  const dynamics::SpacecraftPlant plant(100.0, J);
  dynamics::SpacecraftState y;
  y.R[0] = test::random_rotation();
  y.x.segment<3>(0) = test::random_vector_in_ball(0.05);
  const Quat q_id = lie::rotation_to_quat(test::random_rotation());
  Quat q_ib = lie::rotation_to_quat(y.R[0]);
  if (attitude_error(q_id, q_ib)(0) < 0) q_ib = -q_ib;
  dynamics::SpacecraftInputs u;
  std::vector<double> stops;
  for (int k = 1; k <= static_cast<int>(seconds * 10.0); ++k) stops.push_back(0.1 * k);
  bool finite = true;
  auto sample = [&](double, const dynamics::SpacecraftState& s) {
    const Quat q = lie::rotation_to_quat(s.R[0]);
    q_ib = q.dot(q_ib) < 0 ? Quat(-q) : q;
    u.tau_b = pid.step(q_ib, dynamics::omega_b_of(s), q_id, Vec3::Zero(), 0.1).tau_b;
    finite = finite && u.tau_b.allFinite() && u.tau_b.norm() < 1e9;
    return finite;
  };
  (void)sample(0.0, y);
  integrate::IntegratorSettings settings;
  settings.step = 0.1;
  try {
    (void)integrate::integrate(
        [&](double, const dynamics::SpacecraftState& s) { return plant.derivative(s, u); }, y, 0.0,
        std::span<const double>(stops), settings,
        [&](double t, dynamics::SpacecraftState& s) { return sample(t, s); },
        [](double, const dynamics::SpacecraftState&) {});
  } catch (const std::exception&) {
    return HUGE_VAL;
  }
  return finite ? attitude_error(q_id, q_ib).tail<3>().norm() : HUGE_VAL;
}

TEST(QuaternionPid, InertiaShapingGivesEveryAxisTheSameBandwidth) {
  // Principal moments 2, 4000 and 4001 kg m^2 on random axes: the scalar gains of a 0.3 rad/s PD
  // for J_max make the 2 kg m^2 axis's sampled derivative term 120 times too large (it
  // diverges); shaped by S = J/J_max (with ω × J ω) every axis converges at 0.3 rad/s.
  for (unsigned trial = 0; trial < 10; ++trial) {
    const lie::Mat3 Ra = test::random_rotation();
    const lie::Mat3 J = Ra * Vec3(2.0, 4000.0, 4001.0).asDiagonal() * Ra.transpose();
    const double w = 0.3, J_max = 4001.0;
    QuaternionPidGains g{2.0 * w * w * J_max, 0.0, 4.0 * w * J_max};
    EXPECT_FALSE(final_error(J, QuaternionPid(g), 600.0) < 1e-3) << "trial " << trial;
    g.shaped = true;
    g.shaping = J / J_max;
    g.shaping_scale = J_max;
    EXPECT_LT(final_error(J, QuaternionPid(g), 600.0), 1e-6) << "trial " << trial;
  }
}

}  // namespace
}  // namespace attiguard::control
