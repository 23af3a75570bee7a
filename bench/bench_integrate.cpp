// Benchmarks of the RKMK integrators on the rigid-body plant under the PD law (3) of the
// PET-ERG paper: one RKMK4 step, and a 10⁵-step closed-loop simulation.
#include <benchmark/benchmark.h>

#include "attiguard/control/pd_so3.hpp"
#include "attiguard/dynamics/attitude_state.hpp"
#include "attiguard/integrate/integrator.hpp"

namespace {

using attiguard::dynamics::AttitudeState;
using attiguard::lie::Mat3;
using attiguard::lie::Vec3;

struct PdLoop {
  attiguard::dynamics::RigidBody body{Vec3(1.0, 2.0, 3.0).asDiagonal().toDenseMatrix()};
  Mat3 R_g = attiguard::lie::exp(Vec3(0.0, 1.5707963267948966, 0.0));
  attiguard::control::PdGains gains{5.0, 1.0};
  AttitudeState::Tangent operator()(double, const AttitudeState& y) const noexcept {
    return attiguard::dynamics::attitude_derivative(
        body, y, attiguard::control::pd_torque(y.R[0], y.x, R_g, gains));
  }
};

AttitudeState initial() {
  AttitudeState y;
  y.x = Vec3(0.2, 0.3, 0.4);
  return y;
}

void BM_Rkmk4Step(benchmark::State& state) {
  PdLoop f;
  AttitudeState y = initial();
  double t = 0.0;
  for (auto _ : state) {
    y = attiguard::integrate::rkmk4_step(f, t, y, 1e-3);
    t += 1e-3;
    benchmark::DoNotOptimize(y);
  }
}
BENCHMARK(BM_Rkmk4Step);

void BM_PdClosedLoop100kSteps(benchmark::State& state) {
  PdLoop f;
  attiguard::integrate::IntegratorSettings s;
  s.method = attiguard::integrate::Method::rkmk4;
  s.step = 1e-3;
  for (auto _ : state) {
    AttitudeState y = initial();
    attiguard::integrate::RkmkIntegrator<AttitudeState> integ(s);
    double t = 0.0;
    integ.advance_to(f, y, t, 100.0, [](double, const AttitudeState&) {});
    benchmark::DoNotOptimize(y);
  }
  state.counters["steps"] = 1e5;
}
BENCHMARK(BM_PdClosedLoop100kSteps)->Unit(benchmark::kMillisecond);

}  // namespace
