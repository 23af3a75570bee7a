// Benchmarks of the slew planner (docs/slew-planner.md): a whole plan_slew (roadmap, IPOPT
// solves, dense check) on a craft with 3 cones and on one with 16 cones. Issue 43 asks for
// ≤ 0.1 s and ≤ 0.5 s on one core; the figures are in docs/performance.md, "Slew planner". And
// one choice of the progress governor's rate (issue 44).
#include <benchmark/benchmark.h>

#include <cstdint>
#include <numbers>
#include <stdexcept>

#include "attiguard/control/so3_tracking.hpp"
#include "attiguard/governor/cone_constraint.hpp"
#include "attiguard/governor/progress_governor.hpp"
#include "attiguard/lie/so3.hpp"
#include "attiguard/plan/slew_planner.hpp"

namespace {

using attiguard::governor::keep_in_cone;
using attiguard::governor::keep_out_cone;
using attiguard::lie::Mat3;
using attiguard::lie::Vec3;
using attiguard::plan::SlewProblem;

constexpr double kDeg = std::numbers::pi / 180.0;

/// A 40 kg-class craft with products of inertia.
Mat3 craft_inertia() {
  Mat3 J;
  J << 2.4, 0.12, -0.08,  //
      0.12, 3.1, 0.05,    //
      -0.08, 0.05, 3.9;
  return J;
}

/// A 150 deg slew with a star tracker (+z) that keeps 35 deg off the Sun and 25 deg off the
/// Earth limb, and an antenna (−x) that keeps within 110 deg of the ground station direction.
SlewProblem three_cones() {
  SlewProblem p;
  p.J_b = craft_inertia();
  p.tau_max = 0.05;
  p.R_target = attiguard::lie::exp(Vec3(0.3, 1.0, 0.2).normalized() * 150.0 * kDeg);
  p.cones.push_back(keep_out_cone(Vec3::UnitZ(), Vec3(0.9, 0.1, 0.45), 35.0 * kDeg));
  p.cones.push_back(keep_out_cone(Vec3::UnitZ(), Vec3(-0.2, -0.9, 0.3), 25.0 * kDeg));
  const Vec3 station = (-Vec3::UnitX() - p.R_target * Vec3::UnitX() + Vec3(0.0, 0.3, 0.0)).normalized();
  p.cones.push_back(keep_in_cone(-Vec3::UnitX(), station, 110.0 * kDeg));
  p.cone_margin = 1.0 * kDeg;
  return p;
}

/// The same craft and slew among 16 keep-out cones of 8 deg on body +z and +x, their inertial
/// directions from a fixed pseudo-random sequence; cones that hold the start or the target are
/// skipped.
SlewProblem sixteen_cones() {
  SlewProblem p;
  p.J_b = craft_inertia();
  p.tau_max = 0.05;
  p.R_target = attiguard::lie::exp(Vec3(0.3, 1.0, 0.2).normalized() * 150.0 * kDeg);
  std::uint64_t state = 0x9e3779b97f4a7c15ULL;
  const auto uniform = [&state] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(state >> 11) * 0x1.0p-53 * 2.0 - 1.0;
  };
  const double alpha = 8.0 * kDeg;
  for (int tries = 0; p.cones.size() < 16 && tries < 10000; ++tries) {
    const Vec3 axis_b = p.cones.size() % 2 == 0 ? Vec3::UnitZ() : Vec3::UnitX();
    const Vec3 s(uniform(), uniform(), uniform());
    if (s.norm() < 0.2 || s.norm() > 1.0) continue;
    const Vec3 avoid_i = s.normalized();
    const double clear = alpha + 5.0 * kDeg;
    if (std::acos(avoid_i.dot(p.R_start * axis_b)) < clear ||
        std::acos(avoid_i.dot(p.R_target * axis_b)) < clear)
      continue;
    p.cones.push_back(keep_out_cone(axis_b, avoid_i, alpha));
  }
  if (p.cones.size() != 16) throw std::logic_error("sixteen_cones: generator ran dry");
  p.cone_margin = 0.5 * kDeg;
  return p;
}

void plan(benchmark::State& state, const SlewProblem& problem) {
  attiguard::plan::PlanReport report;
  for (auto _ : state) {
    const attiguard::plan::PlannedSlew planned = attiguard::plan::plan_slew(problem);
    report = planned.report;
    benchmark::DoNotOptimize(report.duration);
  }
  state.counters["ratio"] = report.ratio;
  state.counters["solves"] = report.solves;
  state.counters["iterations"] = report.iterations;
  state.counters["ways"] = report.ways_tried;
  state.counters["intervals"] = report.intervals;
}

void BM_PlanSlewThreeCones(benchmark::State& state) { plan(state, three_cones()); }
void BM_PlanSlewSixteenCones(benchmark::State& state) { plan(state, sixteen_cones()); }

/// One ProgressGovernor::choose_rate (docs/pet-erg.md, section 16.1) on the three-cone plan, at
/// mid-slew: on the plan (the first candidate, ṡ = 1, is admissible: the cheapest case) or 30
/// deg off it and turning away (all 32 candidates fail: the dearest case).
void choose_rate(benchmark::State& state, bool on_plan) {
  const SlewProblem p = three_cones();
  const attiguard::plan::PlannedSlew planned = attiguard::plan::plan_slew(p);
  const double T = planned.plan.duration();
  const attiguard::governor::ProgressGovernor g(planned.plan, p.cones, p.tau_max,
                                                attiguard::control::TrackingGains{0.02, 0.05},
                                                0.02 * T, 0.05);
  const attiguard::governor::SlewPlanSample s = planned.plan.evaluate(0.5 * T);
  const Mat3 R = on_plan ? s.R_ib : Mat3(s.R_ib * attiguard::lie::exp(Vec3(0.5236, 0.0, 0.0)));
  const Vec3 w = on_plan ? s.omega_b : Vec3(-s.omega_b);
  double rate = 0.0;
  for (auto _ : state) {
    rate = g.choose_rate(0.5 * T, R, w);
    benchmark::DoNotOptimize(rate);
  }
  state.counters["rate"] = rate;
}
void BM_ProgressGovernorChooseRateOnThePlan(benchmark::State& state) { choose_rate(state, true); }
void BM_ProgressGovernorChooseRateOffThePlan(benchmark::State& state) { choose_rate(state, false); }

}  // namespace

BENCHMARK(BM_PlanSlewThreeCones)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlanSlewSixteenCones)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ProgressGovernorChooseRateOnThePlan)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ProgressGovernorChooseRateOffThePlan)->Unit(benchmark::kMicrosecond);
