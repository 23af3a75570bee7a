#include "attiguard/control/pd_so3.hpp"

#include <gtest/gtest.h>

#include "attiguard/dynamics/attitude_state.hpp"
#include "attiguard/integrate/integrator.hpp"
#include "test_support.hpp"

namespace attiguard::control {
namespace {

TEST(PdSo3, TorqueTurnsTowardsTheReference) {
  // R = I, R_g = 90° about y: the proportional torque is k_p sin θ about +y.
  const Mat3 R_g = lie::exp(Vec3(0, 1.5707963267948966, 0));
  const Vec3 tau = pd_torque(Mat3::Identity(), Vec3::Zero(), R_g, {5.0, 1.0});
  EXPECT_LT((tau - Vec3(0, 5.0, 0)).norm(), 1e-14);
  EXPECT_LT((pd_torque(R_g, Vec3(1, 2, 3), R_g, {5.0, 1.0}) + Vec3(1, 2, 3)).norm(), 1e-14);
}

TEST(PdSo3, LyapunovDerivativeIsMinusKdOmegaSquared) {
  // V̇ = −k_d ‖ω‖² along the closed loop (PET-ERG paper, Sec. III-A), by finite differences.
  const dynamics::RigidBody body(Vec3(1, 2, 3).asDiagonal().toDenseMatrix());
  const PdGains gains{5.0, 1.3};
  for (int i = 0; i < 20; ++i) {
    const Mat3 R_g = test::random_rotation();
    dynamics::AttitudeState y;
    y.R[0] = test::random_rotation();
    y.x = test::random_vector_in_ball(1.0);
    auto f = [&](double, const dynamics::AttitudeState& s) {
      return dynamics::attitude_derivative(body, s, pd_torque(s.R[0], s.x, R_g, gains));
    };
    const double h = 1e-5;
    const auto yp = integrate::rkmk4_step(f, 0.0, y, h);
    const auto ym = integrate::rkmk4_step(f, 0.0, y, -h);
    const double Vdot = (pd_lyapunov(body.inertia(), yp.R[0], yp.x, R_g, gains) -
                         pd_lyapunov(body.inertia(), ym.R[0], ym.x, R_g, gains)) /
                        (2 * h);
    EXPECT_NEAR(Vdot, -gains.kd * y.x.squaredNorm(), 1e-8);
  }
}

}  // namespace
}  // namespace attiguard::control
