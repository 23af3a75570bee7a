// Benchmarks of the PET-ERG governor (PET-ERG paper, eqs. (3)-(6)): one governor + controller
// evaluation, one flight-loop step, the offline Γ_d, and the whole Sec. V scenario (60 s).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include "attiguard/control/torque_quantizer.hpp"
#include "attiguard/dynamics/reaction_wheel_array.hpp"
#include "attiguard/governor/attitude_governor.hpp"
#include "attiguard/governor/polytope_torque_threshold.hpp"
#include "attiguard/governor/torque_threshold.hpp"
#include "attiguard/scenario/dispersion.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/read_pet_erg.hpp"
#include "attiguard/sim/pet_erg_run.hpp"
#include "attiguard/sim/pet_erg_scenario.hpp"
#include "attiguard/sim/planned_run.hpp"

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
// allocation u = A⁺τ to the wheels, as on board, on the paper's craft with one fixed state.
// The step of a flight-like scenario, with robust or nominal margins: BM_RobustWheelFlightStep.
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

// ---- the flight-loop step of examples/pet_erg_robust_campaign.toml (issue 14) ----

/// What the flight software receives at control instant k: t_k and the measured (R, ω).
struct MeasuredSample {
  double t{0.0};
  Mat3 R_ib{Mat3::Identity()};
  Vec3 omega_b{Vec3::Zero()};
};

/// The measured states of a flight loop and R_g after each of its steps (to check that the
/// replay is that flight loop; kept apart so that the replayed ring stays small, 1.6 MB).
struct FlightRecord {
  std::vector<MeasuredSample> ring;
  std::vector<Mat3> R_g;
};

/// The nominal scenario of an example campaign file (its [dispersions] removed), parsed by the
/// `pet_erg` kind: the governor parameters, cones and wheels are the flight loop's own.
attiguard::sim::PetErgScenario example_scenario(const std::string& name) {
  const auto doc = attiguard::scenario::load_document(std::string(ATTIGUARD_SOURCE_DIR) + "/examples/" + name);
  return attiguard::scenario::parse_pet_erg(attiguard::scenario::nominal_document(doc));
}

/// The measured states of every control instant of the scenario's own flight loop
/// (simulate_pet_erg with one output row per control period; each true state measured by the
/// scenario's sensor model with the sample index the flight loop uses), so that the benchmark
/// replays the states the governor really sees over the whole manoeuvre.
FlightRecord measured_states(attiguard::sim::PetErgScenario sc) {
  sc.output_interval = sc.control_period;
  FlightRecord rec;
  (void)attiguard::sim::simulate_pet_erg(
      sc, [&](double t, const attiguard::sim::PetErgState& y, const Mat3&,
              const attiguard::governor::GovernorOutput&) {
        const auto k = static_cast<std::uint64_t>(rec.ring.size());
        const auto m = sc.imperfections.sensor.measure(y.R[0], y.x, k);
        rec.ring.push_back({t, m.R_ib, m.omega_b});
        rec.R_g.push_back(y.R[1]);
      });
  return rec;
}

// One control instant of the pet_erg flight loop (docs/pet-erg.md, sections 11-13;
// sim::HeldActuation::control, without the sensor draw: the measured state comes from the ring above): R_d(t),
// AttitudeGovernor::step on the measured state, quantisation of the torque, allocation u = A⁺τ
// to the 4 wheels. The governor and the wheels are built as the flight loop builds them
// (sim::design_governor of the parsed example). The states are replayed in
// order over the whole 1500 s manoeuvre; at its end the governor is reset to R_g(0) and the
// manoeuvre replays (the reset is timed, once per 15 001 steps). Arg 1: robust margins
// (examples/pet_erg_robust_campaign.toml), arg 0: nominal margins (its _nominal twin).
void BM_RobustWheelFlightStep(benchmark::State& state) {
  const bool robust = state.range(0) == 1;
  const auto sc = example_scenario(robust ? "pet_erg_robust_campaign.toml"
                                          : "pet_erg_robust_campaign_nominal.toml");
  if ((sc.margins == attiguard::governor::Margins::robust) != robust || sc.wheels.size() != 4) {
    state.SkipWithError("the example does not have the expected margins and 4 wheels");
    return;
  }
  const FlightRecord rec = measured_states(sc);
  const std::vector<MeasuredSample>& ring = rec.ring;
  const attiguard::governor::GovernorDesign design = attiguard::sim::design_governor(sc);
  AttitudeGovernor gov(design.params, design.cones);
  const attiguard::dynamics::ReactionWheelArray array(sc.wheels);
  const double quantum = sc.imperfections.torque_quantum;
  // Untimed: the replay moves R_g exactly as the simulated flight loop did.
  gov.reset(0.0, sc.R_g0);
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const MeasuredSample& m = ring[i];
    (void)gov.step(m.t, m.R_ib, m.omega_b, sc.desired.at(m.t));
    if (!(attiguard::lie::distance(gov.reference(), rec.R_g[i]) < 1e-9)) {
      state.SkipWithError("the replayed governor departs from the flight loop's R_g");
      return;
    }
  }
  gov.reset(0.0, sc.R_g0);
  std::size_t k = 0;
  long samples = 0;
  for (auto _ : state) {
    const MeasuredSample& m = ring[k];
    const auto& out = gov.step(m.t, m.R_ib, m.omega_b, sc.desired.at(m.t));
    const auto u = array.allocate(attiguard::control::quantize_torque(out.tau_b, quantum));
    benchmark::DoNotOptimize(u);
    samples += out.sampled ? 1 : 0;
    if (++k == ring.size()) {
      k = 0;
      gov.reset(0.0, sc.R_g0);
    }
  }
  state.counters["ring"] = static_cast<double>(ring.size());
  state.counters["sampled"] = benchmark::Counter(static_cast<double>(samples), benchmark::Counter::kAvgIterations);
}
BENCHMARK(BM_RobustWheelFlightStep)->ArgName("robust")->Arg(0)->Arg(1);

// The same flight as BM_RobustWheelFlightStep/robust:0 (examples/pet_erg_robust_campaign_nominal.toml:
// 4 wheels, 10 Hz, one period of delay, quantisation, sensor errors, adversarial disturbance),
// flown in the planned mode (docs/pet-erg.md, section 16.2; the example's rest-to-rest twin: ω_0 = 0,
// the tracking gains derived): one control instant = PlannedGovernor::step on the measured state
// (delay prediction, choice of ṡ, tracking law, saturation), quantisation and the allocation
// u = A⁺τ to the wheels. The measured states of the simulated flight loop are replayed in order
// (the replay is checked against the flight's clock σ); at the end the governor is reset.
void BM_PlannedWheelFlightStep(benchmark::State& state) {
  auto sc = example_scenario("pet_erg_robust_campaign_nominal.toml");
  sc.params.mode = GovernorMode::planned;
  sc.omega0_b = Vec3::Zero();
  sc.derived.kp_derived = sc.derived.kd_derived = true;
  const attiguard::sim::PlannedSetup setup = attiguard::sim::planned_setup(sc);
  sc.output_interval = sc.control_period;
  std::vector<MeasuredSample> ring;
  std::vector<double> sigma;
  (void)attiguard::sim::simulate_planned(
      sc, attiguard::sim::PlannedRowObserver([&](double t, const attiguard::sim::PetErgState& y, const Mat3&,
                                                 const attiguard::governor::GovernorOutput&,
                                                 const attiguard::governor::PlannedOutput& p) {
        const auto m = sc.imperfections.sensor.measure(y.R[0], y.x, static_cast<std::uint64_t>(ring.size()));
        ring.push_back({t, m.R_ib, m.omega_b});
        sigma.push_back(p.sigma);
      }));
  attiguard::governor::PlannedGovernor gov(setup.planned.plan, setup.run.cones, setup.params);
  const attiguard::dynamics::ReactionWheelArray array(sc.wheels);
  const double quantum = sc.imperfections.torque_quantum;
  gov.reset(0.0);
  for (std::size_t i = 0; i < ring.size(); ++i) {  // untimed: the replay is the flight
    (void)gov.step(ring[i].t, ring[i].R_ib, ring[i].omega_b);
    if (!(std::abs(gov.clock().sigma_at(ring[i].t) - sigma[i]) < 1e-9)) {
      state.SkipWithError("the replayed governor departs from the flight loop's clock");
      return;
    }
  }
  gov.reset(0.0);
  std::size_t k = 0;
  long samples = 0;
  for (auto _ : state) {
    const MeasuredSample& m = ring[k];
    const auto& out = gov.step(m.t, m.R_ib, m.omega_b);
    const auto u = array.allocate(attiguard::control::quantize_torque(out.tau_b, quantum));
    benchmark::DoNotOptimize(u);
    samples += out.sampled ? 1 : 0;
    if (++k == ring.size()) {
      k = 0;
      gov.reset(0.0);
    }
  }
  state.counters["ring"] = static_cast<double>(ring.size());
  state.counters["sampled"] = benchmark::Counter(static_cast<double>(samples), benchmark::Counter::kAvgIterations);
}
BENCHMARK(BM_PlannedWheelFlightStep);

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
