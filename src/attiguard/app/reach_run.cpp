#include "attiguard/app/reach_run.hpp"

#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "attiguard/core/errors.hpp"
#include "attiguard/io/csv_writer.hpp"
#include "attiguard/io/interruption.hpp"
#include "attiguard/io/json_file.hpp"
#include "attiguard/io/json_values.hpp"
#include "attiguard/io/partial_file.hpp"
#include "attiguard/lie/quaternion.hpp"
#include "attiguard/parallel/parallel_for.hpp"
#include "attiguard/reach/adversarial.hpp"
#include "attiguard/reach/auto_split.hpp"
#include "attiguard/reach/boundary.hpp"
#include "attiguard/reach/geodesic.hpp"
#include "attiguard/reach/metrics.hpp"
#include "attiguard/reach/partition.hpp"

namespace attiguard::app {

using namespace attiguard::reach;  // the driver of reach/ (ConReach, partition, safety)

namespace {

nlohmann::json mat_json(const Mat3& M) {
  nlohmann::json a = nlohmann::json::array();
  for (int i = 0; i < 3; ++i) a.push_back({M(i, 0), M(i, 1), M(i, 2)});
  return a;
}

/// The exp chart in which every attitude ball of every cell fits best (smallest max of
/// ‖Ψ_i(R_c)‖ + r/√λ_min(Q)); −1 when none holds them all: then each boundary point is given in
/// its own best chart (docs/reach.md, "Representation").
int choose_chart(const std::vector<ReachResult>& results) {
  double best = std::numeric_limits<double>::infinity();
  int chart = 0;
  for (int c = 0; c < 4; ++c) {
    double worst = 0.0;
    for (const ReachResult& res : results) {
      worst = std::max(worst, chart_coordinates(c, res.nominal.front().R).norm() +
                                  attitude_enclosure_radius(attitude_schur({res.Q0, res.S0, res.P0}), res.r0));
      for (const ReachStep& st : res.steps) {
        worst = std::max(worst, chart_coordinates(c, st.R).norm() + st.attitude_radius);
      }
    }
    if (worst < best) {
      best = worst;
      chart = c;
    }
  }
  return best < std::numbers::pi - 1e-3 ? chart : -1;
}

/// reach.json's record of one step of the first cell (docs/reach.md, "Outputs").
nlohmann::json step_json(const ReachStep& st, const SafetyVerdict& verdict) {
  nlohmann::json trials = nlohmann::json::array();
  for (const RateTrial& t : st.trials) {
    trials.push_back({{"c", t.c}, {"feasible", t.feasible}, {"enclosure_radius", t.enclosure_radius}});
  }
  return {{"index", st.index}, {"t", st.t0}, {"t_end", st.t1}, {"c", st.c},
          {"c_identity", st.c_identity}, {"Q", mat_json(st.Q)}, {"S", mat_json(st.S)}, {"P", mat_json(st.P)},
          {"r", st.r},
          {"omega_box", {{"lower", io::json_array(st.omega_box.lo)}, {"upper", io::json_array(st.omega_box.hi)}}},
          {"attitude_box_radius", st.attitude_box.radius},
          {"attitude_radius", st.attitude_radius},
          {"omega_half_widths", io::json_array(st.omega_half_widths)},
          {"lmi_exact", st.lmi_exact}, {"lmi_rho", st.lmi_rho},
          {"fallback", st.fallback}, {"sdp_solves", st.sdp_solves},
          {"rigour", st.proved_rigorously ? "rigorous" : "float"},
          {"numerical_allowance", st.numerical_allowance},
          {"nominal_error_R", st.nominal_error_R},
          {"nominal_error_omega", st.nominal_error_omega},
          {"safe", verdict.step_safe.empty() ? true : static_cast<bool>(verdict.step_safe[static_cast<std::size_t>(st.index)])},
          {"trials", trials}};
}

/// reach.json's "final": the last ball of every cell.
nlohmann::json finals_json(const std::vector<ReachResult>& results) {
  nlohmann::json finals = nlohmann::json::array();
  for (const ReachResult& res : results) {
    nlohmann::json f = {{"t", res.steps.empty() ? 0.0 : res.steps.back().t1},
                        {"complete", res.complete},
                        {"steps", res.steps.size()},
                        {"wall_time_s", res.wall_time_s}};
    if (!res.steps.empty()) {
      const ReachStep& last = res.steps.back();
      f["r"] = last.r;
      f["attitude_radius"] = last.attitude_radius;
      f["omega_half_widths"] = io::json_array(last.omega_half_widths);
    }
    if (!res.complete) f["stop_reason"] = res.stop_reason;
    finals.push_back(f);
  }
  return finals;
}

/// reach.json without the chart and the soundness checks (docs/reach.md, "Outputs").
/// What the splitting left unproved, for the verdict's reason (docs/reach.md, "Automatic
/// splitting"): the leaves, why the unproved ones were not split further.
std::string split_summary(const SplitReport& rep, std::size_t leaves) {
  std::ostringstream os;
  os << rep.leaves_unproved << " of " << leaves << " cells unproved after " << rep.cells_split << " splits";
  if (rep.nominal_violations > 0) {
    os << ", " << rep.nominal_violations << " whose own nominal violates the specification (" << rep.first_violation
       << ")";
  }
  if (rep.stalled > 0) os << ", " << rep.stalled << " where smaller cells proved no further";
  if (rep.budget_spent) os << ", work budget spent (" << rep.budget_reason << ")";
  return os.str();
}

/// reach.json's "partition": the leaves, their depths and the work budget (auto_split.hpp).
nlohmann::json partition_json(const ReachScenario& sc, const SplitOutcome& split) {
  const SplitReport& rep = split.report;
  nlohmann::json depths = nlohmann::json::array();
  for (std::size_t c = 0; c < split.cells.size(); ++c) depths.push_back(split.depth[c]);
  return {{"user_cells", static_cast<long>(std::pow(sc.attitude_cells, 3) * std::pow(sc.omega_cells, 3))},
          {"split", sc.split.enabled},
          {"leaves", split.cells.size()},
          {"leaf_depth", depths},
          {"rounds", rep.rounds},
          {"cells_analysed", rep.cells_analysed},
          {"cells_split", rep.cells_split},
          {"max_depth", rep.max_depth},
          {"leaves_unproved", rep.leaves_unproved},
          {"nominal_violations", rep.nominal_violations},
          {"stalled", rep.stalled},
          {"first_nominal_violation", rep.first_violation},
          {"cell_steps", rep.cell_steps},
          {"wall_time_s", rep.seconds},
          {"budget", {{"max_cell_steps", sc.split.max_cell_steps}, {"max_seconds", sc.split.max_seconds}}},
          {"budget_spent", rep.budget_spent},
          {"budget_reason", rep.budget_reason}};
}

nlohmann::json summary_json(const ReachScenario& sc, std::size_t cells,
                            const std::vector<ReachResult>& results, const SafetyVerdict& verdict,
                            double analysis_time) {
  nlohmann::json j;
  j["name"] = sc.name;
  j["kind"] = "reach";
  j["model"] = sc.model;
  // The product metric's rate selection only: the coupled metric chooses its rate itself and
  // refuses rate_mode (docs/reach.md, "Rate selection"), so it is not echoed as if used.
  j["rate_mode"] = sc.settings.metric == reach::MetricKind::product
                       ? nlohmann::json(std::string(reach::kRateModeNames.name(sc.settings.mode)))
                       : nlohmann::json(nullptr);
  j["horizon"] = sc.settings.horizon;
  j["n_steps"] = results.front().steps.size();  // the first cell's (adaptive steps differ per cell)
  j["step_mode"] = sc.settings.adaptive ? "adaptive" : "fixed";
  j["complete"] = verdict.complete;
  long bisections = 0;
  for (const ReachResult& res : results) bisections += res.bisections;
  j["bisections"] = bisections;
  j["cells"] = cells;
  const ReachResult& r0 = results.front();
  j["initial"] = {{"attitude_radius", sc.initial.attitude_radius},
                  {"omega_radius", sc.initial.omega_radius},
                  {"r0", r0.r0}, {"Q0", mat_json(r0.Q0)}, {"S0", mat_json(r0.S0)},
                  {"P0", mat_json(r0.P0)}};
  j["metric"] = std::string(reach::kMetricNames.name(sc.settings.metric));
  j["rigour"] = std::string(reach::kRigourNames.name(sc.settings.rigour));
  j["sdp_solver"] = std::string(reach::kSdpSolverNames.name(sc.settings.sdp.sdp.solver));
  nlohmann::json steps = nlohmann::json::array();
  for (const ReachStep& st : r0.steps) steps.push_back(step_json(st, verdict));
  j["steps"] = steps;
  j["final"] = finals_json(results);
  j["verdict"] = verdict.proved ? (verdict.requested ? "safe" : "not_requested") : "cannot_prove";
  j["first_failure_time"] = verdict.first_failure_time >= 0.0 ? nlohmann::json(verdict.first_failure_time)
                                                              : nlohmann::json(nullptr);
  if (!verdict.reason.empty()) j["safety_reason"] = verdict.reason;
  long solves = 0;  // summed over cells, so the same whichever rank solved them
  for (const ReachResult& res : results) solves += res.sdp_solves;
  j["sdp_solves"] = solves;
  j["wall_time_s"] = analysis_time;
  return j;
}

/// trajectory.csv: the first cell's nominal at every sub-step time.
void write_trajectory_csv(const std::filesystem::path& out_dir, const ReachResult& r0) {
  io::CsvWriter csv(out_dir / "trajectory.csv",
                    {"t", "q_w", "q_x", "q_y", "q_z", "omega_x", "omega_y", "omega_z"});
  for (const NominalPoint& p : r0.nominal) {
    const Eigen::Vector4d q = lie::rotation_to_quat(p.R);
    const std::array<double, 8> row{p.t, q(0), q(1), q(2), q(3), p.omega(0), p.omega(1), p.omega(2)};
    csv.row(row);
  }
  csv.close();
}

/// steps.csv: per cell and step t, c, r, Q, P, the U_i ω box and the attitude enclosure radius.
void write_steps_csv(const std::filesystem::path& out_dir, const std::vector<ReachResult>& results) {
  io::CsvWriter csv(out_dir / "steps.csv",
                    {"cell", "step", "t", "t_end", "c", "r", "attitude_radius", "omega_lo_x",
                     "omega_lo_y", "omega_lo_z", "omega_hi_x", "omega_hi_y", "omega_hi_z", "Q_xx",
                     "Q_yy", "Q_zz", "Q_xy", "Q_xz", "Q_yz", "P_xx", "P_yy", "P_zz", "P_xy",
                     "P_xz", "P_yz", "center_omega_x", "center_omega_y", "center_omega_z"});
  for (std::size_t c = 0; c < results.size(); ++c) {
    for (const ReachStep& st : results[c].steps) {
      const Mat3& Q = st.Q;
      const Mat3& P = st.P;
      const std::vector<double> row{static_cast<double>(c), static_cast<double>(st.index), st.t0, st.t1,
                                    st.c, st.r, st.attitude_radius, st.omega_box.lo(0),
                                    st.omega_box.lo(1), st.omega_box.lo(2), st.omega_box.hi(0),
                                    st.omega_box.hi(1), st.omega_box.hi(2), Q(0, 0), Q(1, 1), Q(2, 2),
                                    Q(0, 1), Q(0, 2), Q(1, 2), P(0, 0), P(1, 1), P(2, 2), P(0, 1),
                                    P(0, 2), P(1, 2), st.omega(0), st.omega(1), st.omega(2)};
      csv.row(row);
    }
  }
  csv.close();
}

/// tube.csv: the state-tube segments (attitude ball radius, ω box) of the safety check.
void write_tube_csv(const std::filesystem::path& out_dir, const std::vector<ReachResult>& results) {
  io::CsvWriter csv(out_dir / "tube.csv", {"cell", "step", "t0", "t1", "attitude_radius", "omega_lo_x",
                                           "omega_lo_y", "omega_lo_z", "omega_hi_x", "omega_hi_y",
                                           "omega_hi_z"});
  for (std::size_t c = 0; c < results.size(); ++c) {
    for (const ReachStep& st : results[c].steps) {
      for (const TubeSegment& s : st.state_tube) {
        const std::vector<double> row{static_cast<double>(c), static_cast<double>(st.index), s.t0, s.t1,
                                      s.attitude.radius, s.omega.lo(0), s.omega.lo(1), s.omega.lo(2),
                                      s.omega.hi(0), s.omega.hi(1), s.omega.hi(2)};
        csv.row(row);
      }
    }
  }
  csv.close();
}

using BoundaryRows = std::vector<std::array<double, 7>>;

/// One cell's boundary.csv rows: the boundary points of its attitude balls in the chart, or,
/// when chart = −1 (no chart holds every ball), each ball in the best chart that holds it and a
/// ball that fits none point by point in the charts of its points (ball_boundary_atlas).
BoundaryRows cell_boundary_rows(std::size_t c, const ReachResult& res, int chart, int points) {
  BoundaryRows rows;
  auto emit = [&](int step, double t, const Mat3& Q, double r, const Mat3& Rc) {
    int ball_chart = chart;
    if (ball_chart < 0 && ball_fits_chart(Q, r, Rc, best_chart(Rc))) ball_chart = best_chart(Rc);
    if (ball_chart >= 0) {
      for (const Vec3& p : ball_boundary(Q, r, Rc, ball_chart, points)) {
        rows.push_back({static_cast<double>(c), static_cast<double>(step), t,
                        static_cast<double>(ball_chart), p(0), p(1), p(2)});
      }
      return;
    }
    for (const AtlasPoint& p : ball_boundary_atlas(Q, r, Rc, points)) {
      rows.push_back({static_cast<double>(c), static_cast<double>(step), t, static_cast<double>(p.chart),
                      p.r(0), p.r(1), p.r(2)});
    }
  };
  // The attitude projection of B_M is inside B_{Q−SP⁻¹Sᵀ} (docs/reach.md, coupled fact 3).
  emit(0, 0.0, attitude_schur({res.Q0, res.S0, res.P0}), res.r0, res.nominal.front().R);
  for (const ReachStep& st : res.steps) {
    emit(st.index + 1, st.t1, attitude_schur(st.metric()), st.r, st.R);
  }
  return rows;
}

/// boundary.csv: the cells' boundaries computed on the scenario's threads, written in cell order.
void write_boundary_csv(const std::filesystem::path& out_dir, const ReachScenario& sc,
                        const std::vector<ReachResult>& results, int chart) {
  std::vector<BoundaryRows> rows(results.size());
  parallel::parallel_for(static_cast<long>(results.size()), sc.threads, [&](long ci) {
    const auto c = static_cast<std::size_t>(ci);
    rows[c] = cell_boundary_rows(c, results[c], chart, sc.boundary_points);
  });
  io::CsvWriter csv(out_dir / "boundary.csv", {"cell", "step", "t", "chart", "r_x", "r_y", "r_z"});
  for (const auto& cell_rows : rows) {
    for (const auto& row : cell_rows) csv.row(row);
  }
  csv.close();
}

/// samples.csv: the kept sampled trajectories in chart coordinates and ω.
void write_samples_csv(const std::filesystem::path& out_dir, const SoundnessReport& rep, int chart) {
  io::CsvWriter csv(out_dir / "samples.csv",
                    {"sample", "t", "r_x", "r_y", "r_z", "omega_x", "omega_y", "omega_z"});
  for (std::size_t s = 0; s < rep.kept.size(); ++s) {
    const SampleTrajectory& tr = rep.kept[s];
    for (std::size_t k = 0; k < tr.t.size(); ++k) {
      const Vec3 rr = chart_coordinates(std::max(chart, 0), tr.R[k]);
      const std::array<double, 8> row{static_cast<double>(s), tr.t[k], rr(0), rr(1), rr(2),
                                      tr.omega[k](0), tr.omega[k](1), tr.omega[k](2)};
      csv.row(row);
    }
  }
  csv.close();
}

nlohmann::json soundness_json(const SoundnessReport& rep) {
  return {{"samples", rep.samples}, {"inside", rep.inside}, {"max_ratio", rep.max_ratio},
          {"tube_inside", rep.tube_inside}, {"tube_max_excess", rep.tube_max_excess},
          {"wall_time_s", rep.wall_time_s}};
}

nlohmann::json adversarial_json(const AdversarialReport& worst) {
  return {{"evaluations", worst.evaluations}, {"worst_ratio", worst.worst_ratio},
          {"worst_ratio_time", worst.worst_ratio_time},
          {"attitude_spread", worst.attitude_spread},
          {"attitude_claimed", worst.attitude_claimed},
          {"attitude_tightness", worst.attitude_claimed / worst.attitude_spread},
          {"omega_spread", io::json_array(worst.omega_spread)},
          {"omega_claimed", io::json_array(worst.omega_claimed)},
          {"omega_tightness", io::json_array(Vec3(worst.omega_claimed.cwiseQuotient(worst.omega_spread)))},
          {"wall_time_s", worst.wall_time_s}};
}

/// The adversarial check's settings: the soundness sampling's step, seed, threads and stop flag.
AdversarialSettings adversarial_settings(const SoundnessSettings& soundness) {
  AdversarialSettings adv;
  adv.step = soundness.step;
  adv.seed = soundness.seed;
  adv.threads = soundness.threads;
  adv.stop = soundness.stop;
  return adv;
}

/// Most cells the adversarial search runs on (run_soundness_checks).
constexpr std::size_t kAdversarialCells = 27;

/// At most `most` indices of [0, n), evenly spread, 0 first (all of them when n ≤ most).
std::vector<std::size_t> spread_indices(std::size_t n, std::size_t most) {
  std::vector<std::size_t> out;
  const std::size_t k = std::min(n, most);
  for (std::size_t i = 0; i < k; ++i) out.push_back(i * n / k);
  return out;
}

/// NumericalError when an optimised or a sampled initial state leaves its ball, or a sample
/// leaves a state-tube segment or U_i.
void throw_if_unsound(const SoundnessReport& rep, const AdversarialReport& worst) {
  if (!(worst.worst_ratio <= 1.0 + 1e-12)) {
    std::ostringstream os;
    os << "soundness check failed: an optimised initial state leaves its ball (ratio "
       << worst.worst_ratio << " at t = " << worst.worst_ratio_time << " s)";
    throw NumericalError(os.str());
  }
  if (rep.inside != rep.samples) {
    std::ostringstream os;
    os << "soundness check failed: " << rep.samples - rep.inside << " of " << rep.samples
       << " sampled trajectories leave their ball (first at t = " << rep.first_violation_time << " s)";
    throw NumericalError(os.str());
  }
  if (rep.tube_inside != rep.samples) {
    std::ostringstream os;
    os << "soundness check failed: " << rep.samples - rep.tube_inside << " of " << rep.samples
       << " sampled trajectories leave a state-tube segment or U_i (first at t = "
       << rep.tube_first_violation_time << " s, by " << rep.tube_max_excess << ")";
    throw NumericalError(os.str());
  }
}

/// Soundness sampling and the adversarial check (adversarial.hpp): their keys into j,
/// samples.csv, and reach.json written before a failed check throws.
void run_soundness_checks(nlohmann::json& j, const ReachScenario& sc,
                          const std::vector<InitialSet>& cells,
                          const std::vector<ReachResult>& results, int chart,
                          const std::filesystem::path& out_dir) {
  const ClosedLoop& loop = *sc.loop;
  SoundnessSettings soundness = sc.soundness;
  soundness.stop = &io::interruption_flag();  // a signal ends the sampling at the next sample
  const SoundnessReport rep = check_soundness(loop, sc.initial, cells, results, soundness);
  io::throw_if_interrupted();
  j["soundness"] = soundness_json(rep);
  write_samples_csv(out_dir, rep, chart);
  // The adversarial search costs 5 × 8 × 41 simulations per cell: beyond kAdversarialCells
  // cells (a split set) it searches that many, evenly spread over the leaves, the first included
  // (docs/reach.md, "Adversarial check and tightness"); the sampled check covers every cell.
  std::vector<InitialSet> searched_cells;
  std::vector<ReachResult> searched;
  for (const std::size_t c : spread_indices(cells.size(), kAdversarialCells)) {
    searched_cells.push_back(cells[c]);
    searched.push_back(results[c]);
  }
  const AdversarialReport worst = adversarial_check(loop, searched_cells, searched, adversarial_settings(soundness));
  io::throw_if_interrupted();
  j["adversarial"] = adversarial_json(worst);
  j["adversarial"]["cells_searched"] = searched_cells.size();
  io::write_json(out_dir / "reach.json", j);
  throw_if_unsound(rep, worst);
}

void throw_if_unsafe(const SafetyVerdict& verdict) {
  if (verdict.requested && !verdict.proved) {
    throw VerificationFailure("reach: safety cannot be proved: " + verdict.reason);
  }
}

}  // namespace

nlohmann::json run_reach(const reach::ReachScenario& sc, const std::filesystem::path& out_dir,
                         const parallel::World& world) {
  const auto wall0 = std::chrono::steady_clock::now();
  if (world.root()) {
    io::ensure_directory(out_dir);
    io::remove_outputs(out_dir, {"reach.json", "trajectory.csv", "steps.csv", "tube.csv",
                                 "boundary.csv", "samples.csv"});
  }
  const SplitOutcome split =
      run_with_splitting(*sc.loop, partition_initial_set(sc.initial, sc.attitude_cells, sc.omega_cells),
                         sc.settings, sc.safety, sc.split, sc.threads, world);
  const std::vector<InitialSet>& cells = split.cells;
  const std::vector<ReachResult>& results = split.results;
  // SIGINT / SIGTERM stop the analysis between its stages (io/interruption.hpp).
  io::throw_if_interrupted();
  const double analysis_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  const SafetyVerdict verdict = verify_safety(sc.safety, results);
  nlohmann::json j = summary_json(sc, cells.size(), results, verdict, analysis_time);
  j["partition"] = partition_json(sc, split);
  if (!verdict.proved && sc.split.enabled) j["safety_reason"] = verdict.reason + "; " + split_summary(split.report, cells.size());

  if (!world.root()) {  // the other ranks reach the same verdict and exit code but write nothing
    j["chart"] = choose_chart(results);
    throw_if_unsafe(verdict);
    return j;
  }
  io::throw_if_interrupted();
  write_trajectory_csv(out_dir, results.front());
  write_steps_csv(out_dir, results);
  write_tube_csv(out_dir, results);

  // Boundary representation in one exp chart when every ball fits it, else ball by ball (-1).
  io::throw_if_interrupted();
  const int chart = choose_chart(results);
  j["chart"] = chart;
  if (sc.boundary_points > 0) write_boundary_csv(out_dir, sc, results, chart);

  io::throw_if_interrupted();
  if (sc.soundness.samples > 0) {
    run_soundness_checks(j, sc, cells, results, chart, out_dir);
  } else {
    j["soundness"] = {{"samples", 0}, {"inside", 0}};
  }
  io::throw_if_interrupted();
  io::write_json(out_dir / "reach.json", j);
  throw_if_unsafe(verdict);
  return j;
}

}  // namespace attiguard::app
