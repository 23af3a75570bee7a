#pragma once
/// @file work_limits.hpp
/// How much work a scenario may ask for before it is refused, before any work starts
/// (docs/errors.md, "Work too large"): integrator steps (or governor / control samples) of a
/// run, rows of its outputs, runs of a campaign and cell-steps of a reach analysis. Beyond them
/// a run would not finish in reasonable time, fill the disk or exhaust the memory. Each limit
/// has a documented default and a command-line flag that raises it (`--max-steps`, …).

#include <string_view>

namespace attiguard::scenario {

/// One of the limits.
enum class WorkLimit {
  run_steps,      ///< integrator steps, governor samples, control samples of one run
  output_rows,    ///< rows of a run's trajectory.csv
  campaign_runs,  ///< runs of one campaign (--runs)
  reach_cells,    ///< reach partition cells × reachability steps
};

/// The limits in force. Defaults: 1e8 steps, 1e7 rows (≈ 1-2 GB of CSV), 1e6 campaign runs,
/// 1e5 reach cell-steps (≈ an hour of SDP solves).
struct WorkLimits {
  double run_steps{1e8};
  double output_rows{1e7};
  double campaign_runs{1e6};
  double reach_cells{1e5};
};

/// The limits in force for this process (the defaults unless set_work_limits was called).
[[nodiscard]] const WorkLimits& work_limits() noexcept;

/// Replaces the limits in force. Called once by the program from its command-line flags, before
/// any scenario is read (not thread-safe against concurrent readers).
void set_work_limits(const WorkLimits& limits) noexcept;

/// The value in force of `limit`.
[[nodiscard]] double limit_value(WorkLimit limit) noexcept;

/// The command-line flag that raises `limit` ("--max-steps", "--max-output-rows", "--max-runs",
/// "--max-cells").
[[nodiscard]] std::string_view limit_flag(WorkLimit limit) noexcept;

/// The limits under the names the scenario readers have always used.
inline constexpr WorkLimit kMaxRunSteps = WorkLimit::run_steps;
inline constexpr WorkLimit kMaxOutputRows = WorkLimit::output_rows;

}  // namespace attiguard::scenario
