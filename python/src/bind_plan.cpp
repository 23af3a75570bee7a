/// @file bind_plan.cpp
/// The slew planner (docs/slew-planner.md) from Python: `_core._plan_slew` plans a rest-to-rest
/// slew and returns the plan sampled as numpy arrays (as plan.csv of `attiguard plan`), its
/// nodes and its report. attiguard.plan_slew (python/package/attiguard/_plan.py) wraps it.

#include <cmath>
#include <cstddef>
#include <numbers>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "attiguard/core/errors.hpp"
#include "attiguard/dynamics/rigid_body.hpp"
#include "attiguard/governor/slew_plan.hpp"
#include "attiguard/plan/slew_planner.hpp"
#include "attiguard/scenario/argument_checks.hpp"
#include "bindings.hpp"

namespace py = pybind11;

namespace attiguard::python {
namespace {

constexpr const char* kPlanLabel = "plan_slew()";
constexpr double kPlanRadToDeg = 180.0 / std::numbers::pi;
constexpr int kPlanMaxPointsPerInterval = 1000;

/// "plan_slew(): KEY: must be WHAT, got X" as an InputError (a ValueError in Python).
[[noreturn]] void plan_argument_error(const std::string& key, const std::string& what, double got) {
  std::ostringstream m;
  m.precision(17);
  m << kPlanLabel << ": " << key << ": must be " << what << ", got " << got;
  throw InputError(m.str());
}

/// The planner's messages ("plan: …") with the callable's name in front ("plan_slew(): …").
std::string plan_message(const std::string& what) {
  const std::string prefix = "plan: ";
  return std::string(kPlanLabel) + ": " +
         (what.starts_with(prefix) ? what.substr(prefix.size()) : what);
}

/// The slew problem from the arguments of plan_slew, each checked as the scenario readers do
/// (docs/python.md, "Validation"): J by the rigid body's inertia check, R_start and R_target by
/// the rotation check, tau_max > 0, headroom in [0, 1), margin in [0, 90) deg as [plan]'s keys
/// (docs/slew-planner.md, "Options").
plan::SlewProblem plan_problem(const lie::Mat3& J, const lie::Mat3& R_start, const lie::Mat3& R_target,
                               double tau_max, std::vector<governor::ConeConstraint> cones,
                               double torque_headroom, double cone_margin_deg) {
  plan::SlewProblem p;
  if (auto e = dynamics::inertia_error(J)) throw InputError(std::string(kPlanLabel) + ": J: " + *e);
  p.J_b = J;
  p.R_start = scenario::checked_rotation_matrix(R_start, "R_start", kPlanLabel);
  p.R_target = scenario::checked_rotation_matrix(R_target, "R_target", kPlanLabel);
  p.tau_max = scenario::checked_number(tau_max, "tau_max", true, kPlanLabel);
  if (!(torque_headroom >= 0.0 && torque_headroom < 1.0)) {
    plan_argument_error("torque_headroom", ">= 0 and < 1", torque_headroom);
  }
  p.torque_headroom = torque_headroom;
  if (!(cone_margin_deg >= 0.0 && cone_margin_deg < 90.0)) {
    plan_argument_error("cone_margin_deg", ">= 0 and < 90 (degrees)", cone_margin_deg);
  }
  p.cone_margin = cone_margin_deg / kPlanRadToDeg;
  if (cones.size() > static_cast<std::size_t>(governor::kMaxCones)) {
    throw InputError(std::string(kPlanLabel) + ": cones: at most " + std::to_string(governor::kMaxCones) +
                     " cones, got " + std::to_string(cones.size()));
  }
  p.cones = std::move(cones);
  return p;
}

/// The plan sampled at `points` points per interval, both ends of each interval included once
/// (app/plan_run.cpp's write_plan_csv: N·points + 1 samples): t, q (scalar first), R, ω, ω̇, τ.
py::dict plan_samples(const governor::SlewPlan& plan, int points) {
  const int N = plan.intervals();
  const py::ssize_t n = static_cast<py::ssize_t>(N) * points + 1;
  py::array_t<double> t(n), q({n, py::ssize_t{4}}), R({n, py::ssize_t{3}, py::ssize_t{3}}),
      w({n, py::ssize_t{3}}), wd({n, py::ssize_t{3}}), tau({n, py::ssize_t{3}});
  auto T = t.mutable_unchecked<1>();
  auto Q = q.mutable_unchecked<2>();
  auto Rm = R.mutable_unchecked<3>();
  auto W = w.mutable_unchecked<2>();
  auto WD = wd.mutable_unchecked<2>();
  auto U = tau.mutable_unchecked<2>();
  const auto nodes = plan.nodes();
  py::ssize_t row = 0;
  for (int k = 0; k < N; ++k) {
    const double ta = nodes[static_cast<std::size_t>(k)].t;
    const double tb = nodes[static_cast<std::size_t>(k + 1)].t;
    const int last = k + 1 == N ? points : points - 1;
    for (int i = 0; i <= last; ++i, ++row) {
      const double ti = ta + (tb - ta) * i / points;
      const governor::SlewPlanSample s = plan.evaluate_in(k, ti);
      T(row) = ti;
      for (int a = 0; a < 4; ++a) Q(row, a) = s.q_ib(a);
      for (int a = 0; a < 3; ++a) {
        W(row, a) = s.omega_b(a);
        WD(row, a) = s.omega_dot_b(a);
        U(row, a) = s.tau_b(a);
        for (int b = 0; b < 3; ++b) Rm(row, a, b) = s.R_ib(a, b);
      }
    }
  }
  py::dict out;
  out["t"] = t;
  out["q"] = q;
  out["R"] = R;
  out["omega_b"] = w;
  out["omega_dot_b"] = wd;
  out["tau_b"] = tau;
  return out;
}

/// The nodes of the plan (docs/slew-planner.md, "The plan as a trajectory") as arrays.
void plan_nodes(const governor::SlewPlan& plan, py::dict& out) {
  const auto nodes = plan.nodes();
  const auto n = static_cast<py::ssize_t>(nodes.size());
  py::array_t<double> t(n), q({n, py::ssize_t{4}}), w({n, py::ssize_t{3}}), tau({n, py::ssize_t{3}});
  auto T = t.mutable_unchecked<1>();
  auto Q = q.mutable_unchecked<2>();
  auto W = w.mutable_unchecked<2>();
  auto U = tau.mutable_unchecked<2>();
  for (py::ssize_t k = 0; k < n; ++k) {
    const governor::SlewPlanNode& node = nodes[static_cast<std::size_t>(k)];
    T(k) = node.t;
    const lie::Quat qk = node.q_ib.normalized();
    for (int a = 0; a < 4; ++a) Q(k, a) = qk(a);
    for (int a = 0; a < 3; ++a) {
      W(k, a) = node.omega_b(a);
      U(k, a) = node.tau_b(a);
    }
  }
  out["t_nodes"] = t;
  out["q_nodes"] = q;
  out["omega_b_nodes"] = w;
  out["tau_b_nodes"] = tau;
}

/// The planner's report (plan.json's figures, docs/slew-planner.md "Outputs"); the smallest
/// cone margin in degrees, None (with its cone and time) without cones.
py::dict plan_report(const plan::PlanReport& r) {
  py::dict d;
  d["duration"] = r.duration;
  d["bang_bang_time"] = r.bang_bang_time;
  d["ratio"] = r.ratio;
  const bool has_cone = r.check.smallest_margin_cone >= 0;
  d["smallest_cone_margin_deg"] =
      has_cone ? py::object(py::float_(r.check.smallest_cone_margin * kPlanRadToDeg)) : py::none();
  d["smallest_margin_cone"] = has_cone ? py::object(py::int_(r.check.smallest_margin_cone)) : py::none();
  d["smallest_margin_time"] =
      has_cone ? py::object(py::float_(r.check.smallest_margin_time)) : py::none();
  d["largest_torque_ratio"] = r.check.largest_torque_ratio;
  d["largest_torque_time"] = r.check.largest_torque_time;
  d["largest_attitude_deviation"] = r.check.largest_attitude_deviation;
  d["intervals"] = r.intervals;
  d["path_waypoints"] = r.path_waypoints;
  d["ways_tried"] = r.ways_tried;
  d["roadmap_attitudes"] = r.roadmap_attitudes;
  d["solves"] = r.solves;
  d["iterations"] = r.iterations;
  d["solver_status"] = r.solver_status;
  d["planning_seconds"] = r.planning_seconds;
  return d;
}

/// plan::plan_slew with the GIL released (it takes up to seconds), its errors renamed to the
/// callable: SetupError → InputError, VerificationFailure and NumericalError kept.
plan::PlannedSlew plan_without_gil(const plan::SlewProblem& problem, const plan::PlannerOptions& options) {
  try {
    py::gil_scoped_release release;
    return plan::plan_slew(problem, options);
  } catch (const InputError& e) {
    throw InputError(plan_message(e.what()));
  } catch (const VerificationFailure& e) {
    throw VerificationFailure(plan_message(e.what()));
  } catch (const NumericalError& e) {
    throw NumericalError(plan_message(e.what()));
  }
}

/// _plan_slew: checks the arguments, plans (docs/slew-planner.md) and returns a dict of the
/// samples, the nodes and the report ("report": a dict).
py::dict plan_slew_arrays(const lie::Mat3& J, const lie::Mat3& R_start, const lie::Mat3& R_target,
                          double tau_max, std::vector<governor::ConeConstraint> cones,
                          double torque_headroom, double cone_margin_deg, int intervals,
                          int points_per_interval) {
  const plan::SlewProblem problem =
      plan_problem(J, R_start, R_target, tau_max, std::move(cones), torque_headroom, cone_margin_deg);
  plan::PlannerOptions options;
  if (intervals != 0 && (intervals < 4 || intervals > 2000)) {
    plan_argument_error("intervals", "0 (derived) or in [4, 2000]", intervals);
  }
  options.intervals = intervals;
  if (points_per_interval < 1 || points_per_interval > kPlanMaxPointsPerInterval) {
    plan_argument_error("points_per_interval", "in [1, " + std::to_string(kPlanMaxPointsPerInterval) + "]",
                        points_per_interval);
  }
  const plan::PlannedSlew planned = plan_without_gil(problem, options);
  py::dict out = plan_samples(planned.plan, points_per_interval);
  plan_nodes(planned.plan, out);
  out["report"] = plan_report(planned.report);
  return out;
}

}  // namespace

void bind_plan(py::module_& m) {
  m.def("_plan_slew", &plan_slew_arrays, py::arg("J"), py::arg("R_start"), py::arg("R_target"),
        py::arg("tau_max"), py::arg("cones"), py::arg("torque_headroom"), py::arg("cone_margin_deg"),
        py::arg("intervals"), py::arg("points_per_interval"),
        "The slew planner (docs/slew-planner.md) on checked arguments: a dict of numpy arrays "
        "(t, q, R, omega_b, omega_dot_b, tau_b at points_per_interval points per interval; "
        "t_nodes, q_nodes, omega_b_nodes, tau_b_nodes) and 'report' (a dict). Used by "
        "attiguard.plan_slew.");
}

}  // namespace attiguard::python
