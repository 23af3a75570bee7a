// ConReach benchmarks (docs/performance.md, "ConReach"): the paper's Sec. 6 example end to end
// (N = 40, N_s = 3; the paper reports 14.73 s in MATLAB/YALMIP/SDPT3 on an Apple M2), one SDP
// (20), and the 10⁴-sample soundness check.

#include <benchmark/benchmark.h>

#include <array>
#include <string>

#include "attiguard/reach/auto_split.hpp"
#include "attiguard/reach/conreach.hpp"
#include "attiguard/reach/contraction_sdp.hpp"
#include "attiguard/reach/dense_sdp.hpp"
#include "attiguard/reach/partition.hpp"
#include "attiguard/reach/soundness.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/read_reach.hpp"

namespace ar = attiguard::reach;

namespace {
const ar::LinearOmegaLoop& paper_loop() {
  static const ar::LinearOmegaLoop loop(ar::Vec3(-2, -1, -3).asDiagonal());
  return loop;
}
const ar::InitialSet kPaperSet{ar::Mat3::Identity(), 0.1, ar::Vec3(0.65, 0.54, 0.61), 0.1};
}  // namespace

static void BM_ConReachPaperLineSearch(benchmark::State& state) {
  for (auto _ : state) {
    const ar::ReachResult res = ar::run_conreach(paper_loop(), kPaperSet, {});
    benchmark::DoNotOptimize(res.steps.back().r);
  }
}
BENCHMARK(BM_ConReachPaperLineSearch)->Unit(benchmark::kMillisecond)->UseRealTime();

static void BM_ConReachPaperMinEnclosure(benchmark::State& state) {
  ar::ConReachSettings s;
  s.mode = ar::RateMode::min_enclosure;
  for (auto _ : state) {
    const ar::ReachResult res = ar::run_conreach(paper_loop(), kPaperSet, s);
    benchmark::DoNotOptimize(res.steps.back().r);
  }
}
BENCHMARK(BM_ConReachPaperMinEnclosure)->Unit(benchmark::kMillisecond)->UseRealTime();

static void BM_ContractionSdpStep0(benchmark::State& state) {
  const ar::Box3 U0{ar::Vec3(0.442, 0.398, 0.361), ar::Vec3(0.750, 0.640, 0.710)};
  const ar::LmiEnclosure enc = paper_loop().lmi_enclosure({}, U0);
  for (auto _ : state) {
    const ar::MetricSolution sol = ar::solve_metric(enc, ar::Mat3::Identity(), ar::Mat3::Identity(),
                                                    0.1871, ar::MetricObjective::max_trace_q, {});
    benchmark::DoNotOptimize(sol.Q);
  }
}
BENCHMARK(BM_ContractionSdpStep0)->Unit(benchmark::kMicrosecond);

// The step-0 metric of BM_ContractionSdpStep0 (the same problem, the same certification) with
// solve_sdp's dense solver (/1, issue 48; docs/reach.md, "Dense SDP solver") and with CSDP alone
// (/0), side by side.
static void BM_DenseSdpPaperStep0(benchmark::State& state) {
  const bool dense = state.range(0) != 0;
  const bool was = ar::dense_sdp_enabled();
  ar::set_dense_sdp_enabled(dense);
  const ar::Box3 U0{ar::Vec3(0.442, 0.398, 0.361), ar::Vec3(0.750, 0.640, 0.710)};
  const ar::LmiEnclosure enc = paper_loop().lmi_enclosure({}, U0);
  const ar::DenseSdpCounts before = ar::dense_sdp_counts();
  for (auto _ : state) {
    const ar::MetricSolution sol = ar::solve_metric(enc, ar::Mat3::Identity(), ar::Mat3::Identity(),
                                                    0.1871, ar::MetricObjective::max_trace_q, {});
    benchmark::DoNotOptimize(sol.Q);
  }
  const ar::DenseSdpCounts after = ar::dense_sdp_counts();
  ar::set_dense_sdp_enabled(was);
  state.SetLabel(dense ? "dense" : "CSDP");
  state.counters["fallbacks"] = static_cast<double>(after.fallback - before.fallback);
}
BENCHMARK(BM_DenseSdpPaperStep0)->Arg(1)->Arg(0)->Unit(benchmark::kMicrosecond);

// The bare solve of BM_DenseSdpPaperStep0's SDP (12 variables, 4 blocks 3×3 + 8 blocks 6×6),
// built once by metric_problem: the dense solver (solve_sdp_dense, issue 48; docs/reach.md,
// "Dense SDP solver") and CSDP (solve_sdp with the dense path off), no certification.
namespace {
const ar::LmiProblem& paper_step0_problem() {
  static const ar::LmiProblem prob = [] {
    const ar::Box3 U0{ar::Vec3(0.442, 0.398, 0.361), ar::Vec3(0.750, 0.640, 0.710)};
    const ar::LmiEnclosure enc = paper_loop().lmi_enclosure({}, U0);
    const ar::StateMetric prev{ar::Mat3::Identity(), ar::Mat3::Zero(), ar::Mat3::Identity()};
    return ar::metric_problem(enc, prev, 0.1871, ar::MetricObjective::max_trace_q, {});
  }();
  return prob;
}
}  // namespace

static void BM_DenseSdpSolveOnly(benchmark::State& state) {
  const ar::LmiProblem& prob = paper_step0_problem();
  int iterations = 0;
  for (auto _ : state) {
    ar::DenseSdpSolver solver(prob);
    const ar::SdpResult res = solver.solve(1e-7);
    iterations = solver.info().iterations;
    benchmark::DoNotOptimize(res.objective);
  }
  state.counters["iterations"] = iterations;
}
BENCHMARK(BM_DenseSdpSolveOnly)->Unit(benchmark::kMicrosecond);

static void BM_CsdpSolveOnly(benchmark::State& state) {
  const ar::LmiProblem& prob = paper_step0_problem();
  const bool was = ar::dense_sdp_enabled();
  ar::set_dense_sdp_enabled(false);
  for (auto _ : state) {
    const ar::SdpResult res = ar::solve_sdp(prob, {}, 1e-7);
    benchmark::DoNotOptimize(res.objective);
  }
  ar::set_dense_sdp_enabled(was);
}
BENCHMARK(BM_CsdpSolveOnly)->Unit(benchmark::kMicrosecond);

// Issue 48's SDP figure: the paper example end to end (its 120 SDPs, run_conreach) with the dense
// solver and its warm start (/1) or CSDP alone (/0); counters: the mean thread CPU time of one
// SDP solve inside solve_sdp and the dense iterations per solve (dense_sdp_counts(); docs/reach.md,
// "Dense SDP solver").
static void BM_PaperSdpPerSolve(benchmark::State& state) {
  const bool dense = state.range(0) != 0;
  ar::ConReachSettings settings;
  settings.sdp.sdp.solver = dense ? ar::SdpSolverKind::dense : ar::SdpSolverKind::csdp;
  const ar::DenseSdpCounts before = ar::dense_sdp_counts();
  for (auto _ : state) {
    const ar::ReachResult res = ar::run_conreach(paper_loop(), kPaperSet, settings);
    benchmark::DoNotOptimize(res.steps.back().r);
  }
  const ar::DenseSdpCounts after = ar::dense_sdp_counts();
  const double solves =
      static_cast<double>(after.dense + after.csdp - before.dense - before.csdp);
  const double seconds = after.dense_seconds + after.csdp_seconds - before.dense_seconds -
                         before.csdp_seconds;
  state.SetLabel(dense ? "dense, warm start" : "CSDP");
  state.counters["us_per_sdp"] = solves > 0 ? 1e6 * seconds / solves : 0.0;
  state.counters["fallbacks"] = static_cast<double>(after.fallback - before.fallback);
  const double dense_solves = static_cast<double>(after.dense - before.dense);
  state.counters["iterations"] =
      dense_solves > 0
          ? static_cast<double>(after.dense_iterations - before.dense_iterations) / dense_solves
          : 0.0;
}
BENCHMARK(BM_PaperSdpPerSolve)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);

// The SDP counts of docs/performance.md and docs/reach.md ("Dense SDP solver"), reproducible: one
// analysis (the cells, the splitting rounds; no soundness check, one thread) of a reach example
// as `attiguard reach` runs it, with the counters of dense_sdp_counts() over it: solves the dense
// solver accepted, called infeasible and handed to CSDP, CSDP's solves, the mean dense
// iterations, and the thread CPU time per solve. /0 conreach_paper, /1 conreach_pd,
// /2 conreach_slow_pd, /3 conreach_hold_partitioned.
static void BM_ExampleSdpCounts(benchmark::State& state) {
  static const std::array<const char*, 4> kExamples{"conreach_paper", "conreach_pd",
                                                    "conreach_slow_pd",
                                                    "conreach_hold_partitioned"};
  const std::string name = kExamples.at(static_cast<std::size_t>(state.range(0)));
  const ar::ReachScenario sc = attiguard::scenario::parse_reach(attiguard::scenario::load_document(
      std::string(ATTIGUARD_SOURCE_DIR) + "/examples/" + name + ".toml"));
  const ar::DenseSdpCounts before = ar::dense_sdp_counts();
  for (auto _ : state) {
    const ar::SplitOutcome out = ar::run_with_splitting(
        *sc.loop, ar::partition_initial_set(sc.initial, sc.attitude_cells, sc.omega_cells),
        sc.settings, sc.safety, sc.split, 1);
    benchmark::DoNotOptimize(out.results.size());
  }
  const ar::DenseSdpCounts after = ar::dense_sdp_counts();
  const double runs = static_cast<double>(state.iterations());
  const auto per_run = [&](long a, long b) { return static_cast<double>(a - b) / runs; };
  state.SetLabel(name);
  state.counters["dense_solved"] = per_run(after.dense, before.dense);
  state.counters["dense_infeasible"] = per_run(after.infeasible, before.infeasible);
  state.counters["csdp_fallbacks"] = per_run(after.fallback, before.fallback);
  state.counters["csdp_solves"] = per_run(after.csdp, before.csdp);
  const double dense = static_cast<double>(after.dense - before.dense);
  state.counters["dense_iterations"] =
      dense > 0 ? static_cast<double>(after.dense_iterations - before.dense_iterations) / dense : 0.0;
  const double solves = static_cast<double>(after.dense + after.infeasible + after.fallback -
                                            before.dense - before.infeasible - before.fallback);
  state.counters["us_per_sdp"] =
      solves > 0 ? 1e6 * (after.dense_seconds + after.csdp_seconds - before.dense_seconds -
                          before.csdp_seconds) / solves
                 : 0.0;
}
BENCHMARK(BM_ExampleSdpCounts)->DenseRange(0, 3)->Iterations(1)->Unit(benchmark::kMillisecond);

static void BM_SoundnessPaper10k(benchmark::State& state) {
  const ar::ReachResult res = ar::run_conreach(paper_loop(), kPaperSet, {});
  ar::SoundnessSettings s;
  s.samples = 10000;
  for (auto _ : state) {
    const ar::SoundnessReport rep = ar::check_soundness(paper_loop(), kPaperSet, {kPaperSet}, {res}, s);
    benchmark::DoNotOptimize(rep.inside);
  }
}
BENCHMARK(BM_SoundnessPaper10k)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(2);
