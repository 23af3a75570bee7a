#pragma once
/// @file plan_command.hpp
/// `attiguard plan SCENARIO [--out DIR] [--plot] [--view]`: the slew planner (docs/slew-planner.md).

#include <filesystem>

namespace attiguard::cli {

/// Arguments of `attiguard plan`.
struct PlanArguments {
  std::filesystem::path scenario;  ///< SCENARIO (kind = "pet_erg")
  std::filesystem::path out_dir;   ///< --out DIR (default out/<scenario stem>_plan)
  bool plot{false};                ///< --plot
  bool view{false};                ///< --view: DIR/view.html (docs/viewer.md)
};

/// Plans the scenario's slew, writes DIR/plan.csv, DIR/plan.json and the resolved scenario (and
/// plots with --plot, view.html with --view), prints the outcome line and the paths written.
/// Exit 4 (with plan.json saying why) when there is no admissible path; exit 3 when the solver
/// fails.
void plan_command(const PlanArguments& args);

}  // namespace attiguard::cli
