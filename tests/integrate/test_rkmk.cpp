#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "attiguard/control/pd_so3.hpp"
#include "attiguard/core/errors.hpp"
#include "attiguard/dynamics/attitude_state.hpp"
#include "attiguard/integrate/integrator.hpp"
#include "test_support.hpp"

namespace attiguard::integrate {
namespace {

using dynamics::AttitudeState;
using dynamics::RigidBody;
using lie::Mat3;
using lie::Vec3;

const RigidBody& body() {
  static const RigidBody b(Vec3(1.0, 2.0, 3.0).asDiagonal().toDenseMatrix());
  return b;
}

auto torque_free() {
  return [](double, const AttitudeState& y) {
    return dynamics::attitude_derivative(body(), y, Vec3::Zero());
  };
}

// PD towards a fixed reference: a closed loop whose solution is not known in closed form.
auto pd_loop() {
  return [](double, const AttitudeState& y) {
    static const Mat3 R_g = lie::exp(Vec3(0.3, 1.2, -0.4));
    const Vec3 tau = control::pd_torque(y.R[0], y.x, R_g, {5.0, 1.0});
    return dynamics::attitude_derivative(body(), y, tau);
  };
}

AttitudeState initial_state() {
  AttitudeState y;
  y.R[0] = lie::exp(Vec3(0.1, -0.2, 0.3));
  y.x = Vec3(0.8, -1.2, 1.5);
  return y;
}

double state_error(const AttitudeState& a, const AttitudeState& b) {
  return lie::distance(a.R[0], b.R[0]) + (a.x - b.x).norm();
}

IntegratorSettings fixed(double h) {
  IntegratorSettings s;
  s.method = Method::rkmk4;
  s.step = h;
  return s;
}

IntegratorSettings adaptive(double tol) {
  IntegratorSettings s;
  s.method = Method::rkmk_dp54;
  s.step = 1e-2;
  s.abs_tol = tol;
  s.rel_tol = tol;
  return s;
}

template <class F>
AttitudeState solve(F f, AttitudeState y, double T, const IntegratorSettings& s) {
  RkmkIntegrator<AttitudeState> integ(s);
  double t = 0.0;
  integ.advance_to(f, y, t, T, [](double, const AttitudeState&) {});
  return y;
}

// Fixed-step DP5 solution: isolates the order of the fifth-order weights.
template <class F>
AttitudeState solve_dp5_fixed(F f, AttitudeState y, double T, int n) {
  const double h = T / n;
  for (int i = 0; i < n; ++i) {
    const double t = i * h;
    y = rkmk_step<AttitudeState>(f, dormand_prince_54, t, y, h, f(t, y)).y;
  }
  return y;
}

TEST(ProductState, RetractAndLocalAreInverse) {
  using S = ProductState<2, 4>;
  for (int i = 0; i < 50; ++i) {
    S y;
    y.R[0] = test::random_rotation();
    y.R[1] = test::random_rotation();
    y.x = Eigen::Vector4d::Random();
    S::Tangent d = S::Tangent::Random();
    const S z = retract<2, 4>(y, d);
    EXPECT_LT((local<2, 4>(y, z) - d).norm(), 1e-12);
  }
}

TEST(Rkmk4, StaysOnSo3OverAMillionStepsWithoutReprojection) {
  AttitudeState y = initial_state();
  RkmkIntegrator<AttitudeState> integ(fixed(1e-3));
  double t = 0.0;
  auto f = torque_free();
  integ.advance_to(f, y, t, 1000.0, [](double, const AttitudeState&) {});
  const double drift = lie::orthonormality_error(y.R[0]);
  std::cout << "[ measured ] RKMK4 ||R^T R - I||_F after " << integ.stats().accepted_steps
            << " steps: " << drift << "\n";
  EXPECT_EQ(integ.stats().accepted_steps, 1'000'000);
  EXPECT_LT(drift, 1e-12);
  EXPECT_NEAR(y.R[0].determinant(), 1.0, 1e-12);
}

TEST(Rkmk4, ConvergesWithOrderFour) {
  const double T = 2.0;
  const AttitudeState ref = solve(pd_loop(), initial_state(), T, fixed(1e-4));
  std::vector<double> err;
  for (double h : {0.1, 0.05, 0.025, 0.0125}) {
    err.push_back(state_error(solve(pd_loop(), initial_state(), T, fixed(h)), ref));
  }
  for (std::size_t i = 1; i < err.size(); ++i) {
    const double order = std::log2(err[i - 1] / err[i]);
    std::cout << "[ measured ] RKMK4 observed order (h=" << 0.1 / (1 << (i - 1)) << " -> half): " << order
              << "\n";
    EXPECT_NEAR(order, 4.0, 0.25);
  }
}

TEST(RkmkDp54, FifthOrderSolutionConvergesWithOrderFive) {
  const double T = 2.0;
  const AttitudeState ref = solve_dp5_fixed(pd_loop(), initial_state(), T, 20000);
  std::vector<double> err;
  for (int n : {80, 160, 320}) {
    err.push_back(state_error(solve_dp5_fixed(pd_loop(), initial_state(), T, n), ref));
  }
  for (std::size_t i = 1; i < err.size(); ++i) {
    const double order = std::log2(err[i - 1] / err[i]);
    std::cout << "[ measured ] RKMK-DP5 observed order (n=" << (80 << (i - 1)) << " -> 2n): " << order
              << " (error " << err[i] << ")\n";
    // Coarser pairs are still pre-asymptotic (observed 5.3 at n = 80); the finest pair is in the
    // asymptotic regime.
    EXPECT_GT(order, 4.8);
    EXPECT_LT(order, i + 1 == err.size() ? 5.2 : 5.5);
  }
}

TEST(RkmkDp54, GlobalErrorFollowsTheTolerance) {
  const double T = 5.0;
  const AttitudeState ref = solve(pd_loop(), initial_state(), T, fixed(1e-4));
  double previous = 1.0;
  for (double tol : {1e-5, 1e-7, 1e-9, 1e-11}) {
    const double e = state_error(solve(pd_loop(), initial_state(), T, adaptive(tol)), ref);
    EXPECT_LT(e, 1000.0 * tol) << "tol=" << tol;
    EXPECT_LT(e, previous) << "tol=" << tol;
    previous = e;
  }
}

TEST(RkmkDp54, TorqueFreeBodyConservesEnergyAndMomentum) {
  AttitudeState y = initial_state();
  const double E0 = body().kinetic_energy(y.x);
  const Vec3 h0 = body().angular_momentum_i(y.R[0], y.x);
  RkmkIntegrator<AttitudeState> integ(adaptive(1e-10));
  double t = 0.0;
  double worst_E = 0.0;
  double worst_h = 0.0;
  auto f = torque_free();
  integ.advance_to(f, y, t, 200.0, [&](double, const AttitudeState& s) {
    worst_E = std::max(worst_E, std::abs(body().kinetic_energy(s.x) - E0) / E0);
    worst_h = std::max(worst_h, (body().angular_momentum_i(s.R[0], s.x) - h0).norm() / h0.norm());
  });
  std::cout << "[ measured ] DP54 tol 1e-10, 200 s: max relative energy drift " << worst_E
            << ", momentum drift " << worst_h << "\n";
  // Local errors of size tol accumulate over the horizon: allow a drift of tol per second.
  EXPECT_LT(worst_E, 200.0 * 1e-10);
  EXPECT_LT(worst_h, 200.0 * 1e-10);
}

TEST(Rkmk4, TorqueFreeBodyConservesEnergyAndMomentumToItsTruncationError) {
  AttitudeState y = initial_state();
  const double E0 = body().kinetic_energy(y.x);
  const Vec3 h0 = body().angular_momentum_i(y.R[0], y.x);
  const AttitudeState end = solve(torque_free(), y, 200.0, fixed(1e-3));
  EXPECT_LT(std::abs(body().kinetic_energy(end.x) - E0) / E0, 1e-9);
  EXPECT_LT((body().angular_momentum_i(end.R[0], end.x) - h0).norm() / h0.norm(), 1e-9);
}

class StopsExactly : public ::testing::TestWithParam<Method> {};

TEST_P(StopsExactly, AtEveryRequestedInstantWithACallback) {
  IntegratorSettings s = GetParam() == Method::rkmk4 ? fixed(0.03) : adaptive(1e-8);
  const std::vector<double> stops{0.1, 0.5, 1.0 / 3.0, 1.37, 2.0};
  std::vector<double> sorted = stops;
  std::sort(sorted.begin(), sorted.end());
  std::vector<double> seen;
  AttitudeState y = initial_state();
  double last_step_t = 0.0;
  integrate(pd_loop(), y, 0.0, sorted, s,
            [&](double t, AttitudeState& state) {
              seen.push_back(t);
              if (t == 1.37) {
                state.x.setZero();  // a jump at the stop is honoured
              }
              return true;
            },
            [&](double t, const AttitudeState&) {
              EXPECT_GT(t, last_step_t);
              last_step_t = t;
            });
  ASSERT_EQ(seen.size(), sorted.size());
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    EXPECT_EQ(seen[i], sorted[i]);  // bit-exact
  }
  EXPECT_EQ(last_step_t, 2.0);
}

TEST_P(StopsExactly, EarlyEndWhenTheCallbackSaysSo) {
  IntegratorSettings s = GetParam() == Method::rkmk4 ? fixed(0.03) : adaptive(1e-8);
  const std::vector<double> stops{0.5, 1.0, 1.5};
  int calls = 0;
  AttitudeState y = initial_state();
  integrate(pd_loop(), y, 0.0, stops, s, [&](double, AttitudeState&) { return ++calls < 2; },
            [](double, const AttitudeState&) {});
  EXPECT_EQ(calls, 2);
}

TEST_P(StopsExactly, NonFiniteDynamicsRaiseNumericalError) {
  IntegratorSettings s = GetParam() == Method::rkmk4 ? fixed(0.01) : adaptive(1e-8);
  auto bad = [](double t, const AttitudeState& y) {
    AttitudeState::Tangent d = dynamics::attitude_derivative(body(), y, Vec3::Zero());
    if (t > 0.5) {
      d(4) = std::nan("");
    }
    return d;
  };
  AttitudeState y = initial_state();
  RkmkIntegrator<AttitudeState> integ(s);
  double t = 0.0;
  EXPECT_THROW(integ.advance_to(bad, y, t, 1.0, [](double, const AttitudeState&) {}),
               NumericalError);
}

INSTANTIATE_TEST_SUITE_P(BothMethods, StopsExactly,
                         ::testing::Values(Method::rkmk4, Method::rkmk_dp54),
                         [](const ::testing::TestParamInfo<Method>& info) {
                           return std::string(info.param == Method::rkmk4 ? "rkmk4" : "rkmk_dp54");
                         });

TEST(Integrator, MaxStepsIsEnforced) {
  IntegratorSettings s = fixed(1e-3);
  s.max_steps = 100;
  AttitudeState y = initial_state();
  RkmkIntegrator<AttitudeState> integ(s);
  double t = 0.0;
  EXPECT_THROW(integ.advance_to(torque_free(), y, t, 1.0, [](double, const AttitudeState&) {}),
               NumericalError);
}

}  // namespace
}  // namespace attiguard::integrate
