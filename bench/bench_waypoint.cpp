// Waypoint guidance (docs/waypoint.md): the whole three-waypoint mission of the paper (Tables I-II) and
// one guidance/controller step. Figures: docs/performance.md, "Waypoint guidance".
#include <benchmark/benchmark.h>

#include <string>

#include "attiguard/guidance/waypoint_sequencer.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/read_waypoint.hpp"
#include "attiguard/sim/waypoint_run.hpp"

namespace {

using namespace attiguard;

sim::WaypointScenario load(const char* name) {
  // The benchmark runs from the build tree; the examples live in the source tree.
  const std::string here = __FILE__;
  const std::string root = here.substr(0, here.rfind("/bench/"));
  return scenario::parse_waypoint(scenario::load_document(root + "/examples/" + name));
}

void BM_WaypointMissionPaper(benchmark::State& state) {
  const sim::WaypointScenario sc = load("waypoint_paper.toml");
  long steps = 0;
  for (auto _ : state) {
    const sim::WaypointSimResult r = sim::simulate_waypoint(sc);
    steps = r.steps;
    benchmark::DoNotOptimize(r.total_time);
  }
  state.counters["steps"] = static_cast<double>(steps);
}
BENCHMARK(BM_WaypointMissionPaper)->Unit(benchmark::kMillisecond);

void BM_WaypointMissionFine(benchmark::State& state) {
  const sim::WaypointScenario sc = load("waypoint_fine.toml");
  for (auto _ : state) {
    const sim::WaypointSimResult r = sim::simulate_waypoint(sc);
    benchmark::DoNotOptimize(r.total_time);
  }
}
BENCHMARK(BM_WaypointMissionFine)->Unit(benchmark::kMillisecond);

void BM_WaypointGuidanceStep(benchmark::State& state) {
  // One sample of the mission (transition rules, desired attitude (23)-(24) evaluated twice,
  // thrust law, PID (27)) at a state with lateral velocity.
  const std::vector<lie::Vec3> wps{lie::Vec3(40000.0, 0.0, 0.0)};
  guidance::MissionParams params;
  guidance::WaypointSequencer mission(params, {20.0, 2.0, 20.0}, wps);
  guidance::MissionInputs in;
  in.v_i = lie::Vec3(50.0, 0.3, -0.2);
  in.p_i = lie::Vec3(30000.0, 5.0, 1.0);
  for (auto _ : state) {
    const guidance::MissionCommand c = mission.step(in);
    benchmark::DoNotOptimize(c.inputs.tau_b);
  }
}
BENCHMARK(BM_WaypointGuidanceStep);

}  // namespace
