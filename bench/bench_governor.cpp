// Benchmarks of the PET-ERG governor (PET-ERG paper, eqs. (3)-(6)): one governor + controller
// evaluation, one flight-loop step, the offline Γ_d, and the whole Sec. V scenario (60 s).
#include <benchmark/benchmark.h>

#include <numbers>
#include <vector>

#include "attiguard/dynamics/reaction_wheel_array.hpp"
#include "attiguard/governor/attitude_governor.hpp"
#include "attiguard/governor/polytope_torque_threshold.hpp"
#include "attiguard/governor/torque_threshold.hpp"
#include "attiguard/scenario/pet_erg_scenario.hpp"
#include "attiguard/sim/pet_erg_run.hpp"

namespace {

using attiguard::governor::AttitudeGovernor;
using attiguard::governor::ConeConstraint;
using attiguard::governor::GovernorMode;
using attiguard::governor::GovernorParams;
using attiguard::lie::Mat3;
using attiguard::lie::Vec3;

GovernorParams paper_params(GovernorMode mode = GovernorMode::pet) {
  GovernorParams p;
  p.mode = mode;
  p.gains = {5.0, 1.0};
  p.J = Vec3(1.0, 2.0, 3.0).asDiagonal();
  p.tau_max = 2.5;
  return p;
}

std::vector<ConeConstraint> paper_cones() {
  return {attiguard::governor::keep_in_cone(Vec3(0, 0, 1), Vec3(-0.791, 0.061, -0.609),
                                            160.0 * std::numbers::pi / 180.0)};
}

const Mat3 kRd = attiguard::lie::exp(Vec3(0.0, std::numbers::pi / 2, 0.0));

/// The paper's Sec. V scenario as a PetErgScenario (same values as examples/pet_erg_paper.toml).
attiguard::sim::PetErgScenario paper_scenario(GovernorMode mode, double step,
                                                   attiguard::integrate::Method method) {
  attiguard::sim::PetErgScenario sc;
  sc.name = "bench";
  sc.params = paper_params(mode);
  sc.cones = paper_cones();
  sc.omega0_b = Vec3(0.2, 0.3, 0.4);
  sc.desired = attiguard::governor::ReferenceSchedule(kRd);
  sc.duration = 60.0;
  sc.output_interval = 60.0;
  sc.integrator.method = method;
  sc.integrator.step = step;
  sc.integrator.abs_tol = 1e-10;
  sc.integrator.rel_tol = 1e-10;
  return sc;
}

// One evaluation of PD law (3) + Γ_d, Γ_g, Γ, ρ_n and the reference rate (6): what the vector
// field of the simulation calls at every stage.
void BM_GovernorEvaluate(benchmark::State& state) {
  const AttitudeGovernor gov(paper_params(), paper_cones());
  const Mat3 R = attiguard::lie::exp(Vec3(0.1, 0.4, -0.2));
  const Mat3 R_g = attiguard::lie::exp(Vec3(0.05, 0.5, -0.1));
  Vec3 w(0.2, 0.3, 0.4);
  for (auto _ : state) {
    benchmark::DoNotOptimize(w);
    const auto out = gov.evaluate(R, w, R_g, kRd, true);
    benchmark::DoNotOptimize(out);
  }
}
BENCHMARK(BM_GovernorEvaluate);

// One flight-loop step (propagation of R_g, sampling clock, evaluation), as on board.
void BM_GovernorFlightStep(benchmark::State& state) {
  AttitudeGovernor gov(paper_params(), paper_cones());
  gov.reset(0.0, Mat3::Identity());
  const Mat3 R = attiguard::lie::exp(Vec3(0.1, 0.4, -0.2));
  const Vec3 w(0.02, 0.03, 0.04);
  double t = 0.0;
  for (auto _ : state) {
    t += 1e-3;
    const auto& out = gov.step(t, R, w, kRd);
    benchmark::DoNotOptimize(out.tau_b);
  }
}
BENCHMARK(BM_GovernorFlightStep);

// One step of the pet_erg flight loop with a 4-wheel pyramid (docs/pet-erg.md, sections 10 and
// 12): AttitudeGovernor::step with the bounded reference step and the polytope's Γ_d, then the
// allocation u = A⁺τ to the wheels, as on board. (The robust margins of issue 14 are not
// implemented: this is the nominal step.)
void BM_WheelFlightStep(benchmark::State& state) {
  GovernorParams p = paper_params();
  p.bounded_step = true;
  const auto wheels = attiguard::dynamics::pyramid_wheels(35.26 * std::numbers::pi / 180.0, 1.5, 2.0);
  const attiguard::dynamics::ReactionWheelArray array(wheels);
  std::vector<Vec3> rows;
  std::vector<double> limits;
  for (int i = 0; i < array.count(); ++i) {
    rows.push_back(array.allocation_row(i));
    limits.push_back(array.wheel(i).torque_max);
  }
  p.polytope_gamma_d =
      attiguard::governor::compute_polytope_torque_threshold(p.gains.kp, p.gains.kd, p.J, rows, limits).gamma_d;
  AttitudeGovernor gov(p, paper_cones());
  gov.reset(0.0, Mat3::Identity());
  const Mat3 R = attiguard::lie::exp(Vec3(0.1, 0.4, -0.2));
  const Vec3 w(0.02, 0.03, 0.04);
  double t = 0.0;
  for (auto _ : state) {
    t += 0.1;
    const auto& out = gov.step(t, R, w, kRd);
    const auto u = array.allocate(out.tau_b);
    benchmark::DoNotOptimize(u);
  }
}
BENCHMARK(BM_WheelFlightStep);

// Offline Γ_d to 1e-12 (once per governor construction).
void BM_TorqueThresholdOffline(benchmark::State& state) {
  for (auto _ : state) {
    const auto th = attiguard::governor::compute_torque_threshold({5.0, 1.0, 1.0, 2.5});
    benchmark::DoNotOptimize(th);
  }
}
BENCHMARK(BM_TorqueThresholdOffline);

// The whole 60 s paper scenario (no file output): arg 0 = PET-ERG RKMK4 h = 5 ms (the example
// file), 1 = PET-ERG RKMK4 h = 10 ms, 2 = PET-ERG RKMK-DP5(4) tol 1e-10, 3 = continuous ERG
// RKMK4 h = 5 ms.
void BM_PaperScenario(benchmark::State& state) {
  using attiguard::integrate::Method;
  const long variant = state.range(0);
  const auto sc =
      variant == 0   ? paper_scenario(GovernorMode::pet, 0.005, Method::rkmk4)
      : variant == 1 ? paper_scenario(GovernorMode::pet, 0.01, Method::rkmk4)
      : variant == 2 ? paper_scenario(GovernorMode::pet, 0.01, Method::rkmk_dp54)
                     : paper_scenario(GovernorMode::continuous, 0.005, Method::rkmk4);
  long steps = 0;
  for (auto _ : state) {
    const auto r = attiguard::sim::simulate_pet_erg(sc);
    steps = r.steps;
    benchmark::DoNotOptimize(r.final_attitude_error);
  }
  state.counters["steps"] = static_cast<double>(steps);
}
BENCHMARK(BM_PaperScenario)->Arg(0)->Arg(1)->Arg(2)->Arg(3)->Unit(benchmark::kMillisecond);

}  // namespace
