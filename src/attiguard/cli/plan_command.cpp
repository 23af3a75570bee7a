/// @file plan_command.cpp
/// `attiguard plan SCENARIO [--out DIR] [--plot] [--view]` (docs/slew-planner.md, "Outputs").

#include "attiguard/cli/plan_command.hpp"

#include <exception>
#include <iostream>

#include <nlohmann/json.hpp>

#include "attiguard/app/outcome_line.hpp"
#include "attiguard/app/output_folder.hpp"
#include "attiguard/app/plan_run.hpp"
#include "attiguard/cli/commands.hpp"
#include "attiguard/cli/view_command.hpp"
#include "attiguard/core/errors.hpp"
#include "attiguard/io/json_file.hpp"
#include "attiguard/io/json_reader.hpp"
#include "attiguard/io/output_records.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/read_pet_erg.hpp"
#include "attiguard/scenario/resolved_scenario.hpp"
#include "attiguard/sim/pet_erg_slew_problem.hpp"

namespace attiguard::cli {
namespace {

/// Plots, the paths written, the outcome line.
void report(const PlanArguments& args, const std::filesystem::path& dir, const nlohmann::json& j,
            bool planned) {
  std::cout << app::plan_outcome_line(j) << '\n';
  std::cout << "Wrote:\n";
  if (planned) std::cout << "  " << (dir / "plan.csv").string() << '\n';
  std::cout << "  " << (dir / "plan.json").string() << "\n  "
            << (dir / scenario::kResolvedScenarioFile).string() << '\n';
  if (args.view && planned) std::cout << "  " << write_run_view(dir).string() << '\n';
  if (args.plot && planned) {
    const PlotOutcome plots = plot_results("plan", dir);
    io::record_plots(dir, plots.written);
    for (const auto& p : plots.written) std::cout << "  " << p.string() << '\n';
    if (plots.skipped_because) std::cerr << "attiguard: warning: no plots: " << *plots.skipped_because << '\n';
  }
  std::cout.flush();
}

void plan_into(const PlanArguments& args, const std::filesystem::path& dir,
               app::OutputFolder& folder) {
  const scenario::Document doc = scenario::load_document(args.scenario);
  const sim::PetErgScenario sc = scenario::parse_pet_erg_slew(doc);
  folder.set_subject("pet_erg", args.scenario.string());
  io::ensure_directory(dir);
  io::write_text(dir, scenario::kResolvedScenarioFile,
                 scenario::resolve_scenario(doc, [](const scenario::Document& d) {
                   (void)scenario::parse_pet_erg_slew(d);
                 }));
  if (const auto refusal = sim::slew_refusal(sc)) {  // not one rest-to-rest slew: at its key
    scenario::fail_in_table(doc, refusal->table, refusal->key, refusal->message);
  }
  nlohmann::json j;
  try {
    j = app::run_plan(sc, dir);
  } catch (const VerificationFailure&) {  // exit 4: a result, with plan.json saying why
    report(args, dir, io::read_json_object(dir / "plan.json"), false);
    folder.finish();
    throw;
  }
  report(args, dir, j, true);
  folder.finish();
}

}  // namespace

void plan_command(const PlanArguments& args) {
  const std::filesystem::path dir =
      args.out_dir.empty() ? std::filesystem::path("out") / (args.scenario.stem().string() + "_plan")
                           : args.out_dir;
  app::OutputFolder folder(dir, app::OutputCommand::plan, true, {args.scenario});
  app::run_in_folder(folder, "pet_erg", args.scenario, [&] { plan_into(args, dir, folder); });
}

}  // namespace attiguard::cli
