#include "attiguard/app/kinds.hpp"

#include "attiguard/io/partial_file.hpp"

#include <array>
#include <chrono>
#include <functional>
#include <string>

#include "attiguard/app/numerical_hints.hpp"
#include "attiguard/app/outcome_line.hpp"
#include "attiguard/core/errors.hpp"
#include "attiguard/io/interruption.hpp"
#include "attiguard/io/json_file.hpp"
#include "attiguard/scenario/read_mission.hpp"
#include "attiguard/scenario/read_pet_erg.hpp"
#include "attiguard/scenario/read_reach.hpp"
#include "attiguard/scenario/read_rigid_body.hpp"
#include "attiguard/scenario/read_waypoint.hpp"
#include "attiguard/sim/mission_kind_prediction.hpp"
#include "attiguard/sim/mission_run.hpp"
#include "attiguard/sim/pet_erg_run.hpp"
#include "attiguard/sim/planned_run.hpp"
#include "attiguard/sim/derived_values_json.hpp"
#include "attiguard/sim/rigid_body_run.hpp"
#include "attiguard/sim/waypoint_run.hpp"
#include "attiguard/sim/waypoint_prediction.hpp"

namespace attiguard::app {

namespace {

using scenario::Document;

/// Passes the rows to the file's sink and stops the run at the next row once SIGINT or SIGTERM
/// arrived (io/interruption.hpp): the run then ends with io::Interrupted and its
/// trajectory.csv.partial holds the rows so far (docs/conventions.md, "Outputs").
class InterruptibleRows final : public io::RowSink {
 public:
  explicit InterruptibleRows(io::RowSink& rows) : rows_(rows) {}
  void begin(const std::vector<std::string>& columns) override { rows_.begin(columns); }
  void row(std::span<const double> values) override {
    if (io::interrupted()) io::throw_if_interrupted();
    rows_.row(values);
  }
  void end() override { rows_.end(); }
  [[nodiscard]] bool wants_rows() const noexcept override { return rows_.wants_rows(); }

 private:
  io::RowSink& rows_;
};

/// Runs `simulate` (rows into the sink the options ask for, returns the summary), then adds
/// wall_time_s and writes DIR/summary.json when files are written: the one place a run's files
/// are written.
nlohmann::json run_with_sink(const RunOptions& options,
                             const std::function<nlohmann::json(io::RowSink&)>& simulate) {
  const auto start = std::chrono::steady_clock::now();
  io::NullRowSink none;
  std::optional<io::CsvRowSink> csv;
  if (options.write_files) {
    io::throw_if_interrupted();
    io::ensure_directory(options.out_dir);
    io::remove_outputs(options.out_dir, {"trajectory.csv", "summary.json"});
    csv.emplace(options.out_dir / "trajectory.csv");
  }
  io::RowSink* file_rows = csv ? static_cast<io::RowSink*>(&*csv) : nullptr;
  std::optional<io::TeeRowSink> tee;
  if (file_rows && options.rows) tee.emplace(*file_rows, *options.rows);
  io::RowSink& chosen = tee ? *tee : file_rows ? *file_rows : options.rows ? *options.rows : none;
  InterruptibleRows interruptible(chosen);  // runs that write files stop at a signal
  io::RowSink& rows = options.write_files ? static_cast<io::RowSink&>(interruptible) : chosen;
  nlohmann::json summary = simulate(rows);
  if (csv) csv->end();  // trajectory.csv complete: renamed from trajectory.csv.partial
  summary["wall_time_s"] =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (options.write_files) io::write_json(options.out_dir / "summary.json", summary);
  return summary;
}

/// `check`'s report of a pet_erg scenario: its governor values, given or derived from the craft
/// (docs/pet-erg.md, section 8).
std::string pet_erg_check_report(const Document& doc) {
  const sim::PetErgScenario sc = scenario::parse_pet_erg(doc);
  // The planned mode plans at set-up: `check` plans and reports what the run would fly with.
  if (sc.params.mode == governor::GovernorMode::planned) {
    try {
      return sim::planned_report(sim::planned_setup(sc));
    } catch (const sim::PlannedSetupRefusal& e) {
      scenario::fail_in_table(doc, e.table(), e.key(), e.message());
    }
  }
  return sim::derived_values_report(sim::governor_values(sc));
}


/// `check`'s report of a waypoint scenario: the mission prediction (docs/waypoint.md, "Prediction").
std::string waypoint_check_report(const Document& doc) {
  return sim::prediction_report(scenario::parse_waypoint(doc));
}

/// `check`'s report of a mission scenario: the mission prediction with the turns at the pace of
/// its governor (docs/mission.md, "Prediction").
std::string mission_check_report(const Document& doc) {
  return sim::mission_prediction_report(scenario::parse_mission(doc));
}

/// `check` of a simulation kind: parse (and validate) only.
template <auto Parse>
void check_kind(const Document& doc) {
  (void)Parse(doc);
}

/// `run` of a simulation kind: Parse the document into the kind's configuration, Simulate it
/// with the rows into the chosen sink (the typed result), Summarize the result (the kind's one
/// summary writer).
template <auto Parse, auto Simulate, auto Summarize>
nlohmann::json run_kind(const Document& doc, const RunOptions& options) {
  const auto config = Parse(doc);
  return run_with_sink(options,
                       [&](io::RowSink& rows) { return Summarize(config, Simulate(config, rows)); });
}

/// `run` of kind pet_erg: run_kind, with the planned mode's set-up refusals located in the file.
nlohmann::json run_pet_erg(const Document& doc, const RunOptions& options) {
  try {
    return run_kind<&scenario::parse_pet_erg, &sim::record_pet_erg, &sim::pet_erg_summary>(doc, options);
  } catch (const sim::PlannedSetupRefusal& e) {
    scenario::fail_in_table(doc, e.table(), e.key(), e.message());
  }
}

/// `run` of kind mission: both flights' results are written even when one failed numerically;
/// then a failure of the scenario's own flight exits 3 (NumericalError) naming it.
/// A run that writes files stops at the next control step of either flight once SIGINT or
/// SIGTERM arrived (io/interruption.hpp), not only at its next output row.
nlohmann::json run_mission(const Document& doc, const RunOptions& options) {
  const auto config = scenario::parse_mission(doc);
  const std::atomic<bool>* stop = options.write_files ? &io::interruption_flag() : nullptr;
  nlohmann::json summary = run_with_sink(options, [&](io::RowSink& rows) {
    return sim::mission_summary(config, sim::record_mission(config, rows, stop));
  });
  if (summary.contains("failure") && summary["failure"].is_string()) {
    throw NumericalError("mission: " + summary["failure"].get<std::string>() +
                         " (its summary, with the twin's results, is written)");
  }
  return summary;
}

// Reachability is an analysis, not a simulation: it has its own subcommand and outputs.
nlohmann::json run_reach(const Document& doc, const RunOptions&) {
  scenario::fail_at(doc, "kind", "scenario kind 'reach' is analysed with `attiguard reach " +
                                     doc.path.string() + " --out DIR`, not `attiguard run`");
}

constexpr std::array<KindHandler, 5> registry{{
    {"rigid_body", "rigid body: torque-free, constant torque, or PD law [PET-ERG eq. (3)] to a fixed attitude",
     &check_kind<&scenario::parse_rigid_body>,
     &run_kind<&scenario::parse_rigid_body, &sim::simulate_rigid_body, &sim::rigid_body_summary>,
     &rigid_body_outcome_line, &rigid_body_numerical_hint},
    {"pet_erg",
     "constrained attitude control: PD law [PET-ERG eq. (3)] with [PET-ERG eqs. (5)-(6)], the ERG [PET-ERG eq. (4)], or none",
     &check_kind<&scenario::parse_pet_erg>,
     &run_pet_erg, &pet_erg_outcome_line, &pet_erg_numerical_hint, &pet_erg_check_report},
    {"waypoint",
     "waypoint tracking with one main thruster, wheels and six RCT (align/accelerate/coast/flip/"
     "decelerate/fine state machine)",
     &check_kind<&scenario::parse_waypoint>,
     &run_kind<&scenario::parse_waypoint, &sim::record_waypoint, &sim::waypoint_summary>,
     &waypoint_outcome_line, nullptr, &waypoint_check_report},
    {"mission",
     "waypoint guidance through the PET-ERG: pointing cones and torque limit kept during the "
     "slews; also flies the unconstrained twin",
     &check_kind<&scenario::parse_mission>, &run_mission, &mission_outcome_line, nullptr, &mission_check_report},
    {"reach",
     "ConReach contraction-based reachability and safety verification (use `attiguard reach`)",
     &check_kind<&scenario::parse_reach>, &run_reach, &reach_outcome_line},
}};

}  // namespace

std::span<const KindHandler> kinds() { return registry; }

const KindHandler& handler_for(const Document& doc) {
  const std::string kind = scenario::scenario_kind(doc);
  for (const KindHandler& h : registry) {
    if (h.name == kind) {
      return h;
    }
  }
  std::string known;
  for (const KindHandler& h : registry) {
    known += (known.empty() ? "" : ", ") + std::string(h.name);
  }
  scenario::fail_at(doc, "kind", "unknown scenario kind '" + kind + "' (known kinds: " + known + ")");
}

}  // namespace attiguard::app
