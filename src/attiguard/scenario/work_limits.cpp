// The work limits in force (docs/errors.md, "Work too large").

#include "attiguard/scenario/work_limits.hpp"

namespace attiguard::scenario {

namespace {
WorkLimits& limits_in_force() noexcept {
  static WorkLimits limits;
  return limits;
}
}  // namespace

const WorkLimits& work_limits() noexcept { return limits_in_force(); }

void set_work_limits(const WorkLimits& limits) noexcept { limits_in_force() = limits; }

double limit_value(WorkLimit limit) noexcept {
  const WorkLimits& l = work_limits();
  switch (limit) {
    case WorkLimit::run_steps: return l.run_steps;
    case WorkLimit::output_rows: return l.output_rows;
    case WorkLimit::campaign_runs: return l.campaign_runs;
    case WorkLimit::reach_cells: return l.reach_cells;
  }
  return 0.0;
}

std::string_view limit_flag(WorkLimit limit) noexcept {
  switch (limit) {
    case WorkLimit::run_steps: return "--max-steps";
    case WorkLimit::output_rows: return "--max-output-rows";
    case WorkLimit::campaign_runs: return "--max-runs";
    case WorkLimit::reach_cells: return "--max-cells";
  }
  return "";
}

}  // namespace attiguard::scenario
