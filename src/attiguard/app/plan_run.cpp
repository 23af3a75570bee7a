#include "attiguard/app/plan_run.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include "attiguard/core/errors.hpp"
#include "attiguard/dynamics/eigenaxis_slew.hpp"
#include "attiguard/io/csv_writer.hpp"
#include "attiguard/io/json_file.hpp"
#include "attiguard/sim/cone_json.hpp"
#include "attiguard/sim/pet_erg_slew_problem.hpp"

namespace attiguard::app {

namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;

double scenario_bang_bang_time(const sim::PetErgScenario& sc) {
  return dynamics::eigenaxis_bang_bang_time(sc.params.J, sc.R0_ib, sc.desired.final_attitude(),
                                            sc.params.tau_max);
}

nlohmann::json common_fields(const sim::PetErgScenario& sc, const plan::SlewProblem& problem) {
  nlohmann::json j;
  j["kind"] = "plan";
  j["name"] = sc.name;
  j["eigenaxis_bang_bang_time"] = scenario_bang_bang_time(sc);
  j["torque_limit"] = problem.tau_max;
  j["torque_headroom"] = problem.torque_headroom;
  j["cone_margin_deg"] = problem.cone_margin * kRadToDeg;
  // The cones as summary.json writes them (sim/cone_json.hpp): `view` draws them from here.
  j["cones"] = nlohmann::json::array();
  for (const governor::ConeConstraint& c : problem.cones) j["cones"].push_back(sim::cone_json(c));
  return j;
}

}  // namespace

nlohmann::json plan_summary(const sim::PetErgScenario& sc, const plan::SlewProblem& problem,
                            const plan::PlannedSlew& planned) {
  const plan::PlanReport& r = planned.report;
  nlohmann::json j = common_fields(sc, problem);
  j["outcome"] = "planned";
  j["duration"] = r.duration;
  const double t_bb = j["eigenaxis_bang_bang_time"].get<double>();
  j["ratio_to_bang_bang"] = t_bb > 0.0 ? nlohmann::json(r.duration / t_bb) : nlohmann::json(nullptr);
  if (r.check.smallest_margin_cone >= 0) {
    j["smallest_cone_margin_deg"] = r.check.smallest_cone_margin * kRadToDeg;
    j["smallest_margin_cone"] = r.check.smallest_margin_cone;
    j["smallest_margin_time"] = r.check.smallest_margin_time;
  } else {
    j["smallest_cone_margin_deg"] = nullptr;
    j["smallest_margin_cone"] = nullptr;
    j["smallest_margin_time"] = nullptr;
  }
  // The dense check's ratio is to the planner's torque limit; plan.json's to [control] tau_max.
  j["largest_torque_ratio"] = r.check.largest_torque_ratio * problem.tau_max / sc.params.tau_max;
  j["largest_torque_time"] = r.check.largest_torque_time;
  j["largest_attitude_deviation"] = r.check.largest_attitude_deviation;
  j["dense_points_per_interval"] = plan::PlannerOptions{}.dense_points_per_interval;
  j["intervals"] = r.intervals;
  j["path_waypoints"] = r.path_waypoints;
  j["ways_tried"] = r.ways_tried;
  j["roadmap_attitudes"] = r.roadmap_attitudes;
  j["solver"] = {{"name", "ipopt"},
                 {"status", r.solver_status},
                 {"iterations", r.iterations},
                 {"solves", r.solves},
                 {"cones_reimposed", r.cones_reimposed}};
  j["planning_time"] = r.planning_seconds;
  return j;
}

void write_plan_csv(const std::filesystem::path& path, const governor::SlewPlan& plan,
                    const sim::PetErgScenario& sc, int points_per_interval) {
  std::vector<std::string> columns{"t",       "q_w",     "q_x",     "q_y",   "q_z",
                                   "omega_x", "omega_y", "omega_z", "tau_x", "tau_y",
                                   "tau_z",   "tau_norm"};
  for (std::size_t i = 0; i < sc.cones.size(); ++i) columns.push_back("margin_" + std::to_string(i));
  io::CsvWriter csv(path, columns);
  std::vector<double> row(columns.size());
  const auto nodes = plan.nodes();
  for (int k = 0; k < plan.intervals(); ++k) {
    const double ta = nodes[static_cast<std::size_t>(k)].t;
    const double tb = nodes[static_cast<std::size_t>(k + 1)].t;
    const int last = k + 1 == plan.intervals() ? points_per_interval : points_per_interval - 1;
    for (int i = 0; i <= last; ++i) {
      const double t = ta + (tb - ta) * i / points_per_interval;
      const governor::SlewPlanSample s = plan.evaluate_in(k, t);
      std::size_t c = 0;
      row[c++] = t;
      for (int q = 0; q < 4; ++q) row[c++] = s.q_ib(q);
      for (int a = 0; a < 3; ++a) row[c++] = s.omega_b(a);
      for (int a = 0; a < 3; ++a) row[c++] = s.tau_b(a);
      row[c++] = s.tau_b.norm();
      for (const governor::ConeConstraint& cone : sc.cones) row[c++] = governor::pointing_margin(cone, s.R_ib);
      csv.row(row);
    }
  }
  csv.close();
}

nlohmann::json run_plan(const sim::PetErgScenario& sc, const std::filesystem::path& dir) {
  const plan::SlewProblem problem = sim::slew_problem(sc);
  plan::PlannedSlew planned;
  try {
    planned = plan::plan_slew(problem, sim::planner_options(sc));
  } catch (const VerificationFailure& e) {
    nlohmann::json j = common_fields(sc, problem);
    j["outcome"] = "no_admissible_path";
    j["reason"] = e.what();
    io::write_json(dir / "plan.json", j);
    throw;
  }
  write_plan_csv(dir / "plan.csv", planned.plan, sc);
  const nlohmann::json j = plan_summary(sc, problem, planned);
  io::write_json(dir / "plan.json", j);
  return j;
}

}  // namespace attiguard::app
