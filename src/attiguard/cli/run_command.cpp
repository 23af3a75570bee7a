/// @file run_command.cpp
/// `attiguard run SCENARIO --out DIR [--plot]`.

#include <iostream>
#include <string>
#include <system_error>
#include <vector>

#include <nlohmann/json.hpp>

#include "attiguard/cli/commands.hpp"
#include "attiguard/cli/output_dir.hpp"
#include "attiguard/cli/export_aem_command.hpp"
#include "attiguard/cli/view_command.hpp"
#include "attiguard/core/errors.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/resolved_scenario.hpp"
#include "attiguard/app/failure.hpp"
#include "attiguard/app/kinds.hpp"
#include "attiguard/app/output_folder.hpp"
#include "attiguard/io/interruption.hpp"
#include "attiguard/io/output_records.hpp"

namespace attiguard::cli {

namespace {

void run_into(const RunArguments& args, app::OutputFolder& folder) {
  const scenario::Document doc = scenario::load_document(args.scenario);
  if (doc.has_top_level("dispersions")) {  // a campaign scenario (docs/campaigns.md)
    throw InputError(args.scenario.string() +
                     ": a campaign scenario ([dispersions]): run it with `attiguard campaign " +
                     args.scenario.string() + " --runs N --out DIR`, or one of its runs with "
                     "`--replay K`");
  }
  const app::KindHandler& handler = app::handler_for(doc);
  folder.set_subject(std::string(handler.name), args.scenario.string());
  make_output_dir(args.out_dir);

  app::RunOptions options;
  options.out_dir = args.out_dir;
  // What this run is computed from, every default filled in (scenario/resolved_scenario.hpp).
  io::write_text(args.out_dir, scenario::kResolvedScenarioFile, scenario::resolve_scenario(doc, handler.check));
  const nlohmann::json summary = [&] {
    try {
      return handler.run(doc, options);
    } catch (const io::Interrupted&) {
      throw;
    } catch (const NumericalError& e) {  // name the key most likely responsible (app/failure.hpp)
      throw NumericalError(app::located_numerical_failure(e.what(), doc));
    }
  }();
  // The one-line outcome (docs/conventions.md, "Outcome line"), then the paths written.
  std::cout << handler.outcome_line(summary) << '\n';

  std::vector<std::filesystem::path> written;
  for (const char* file : {"trajectory.csv", "summary.json", scenario::kResolvedScenarioFile}) {
    const auto path = args.out_dir / file;
    std::error_code ec;
    if (std::filesystem::is_regular_file(path, ec)) written.push_back(path);
  }

  if (args.aem) written.push_back(write_run_aem(args.scenario, args.out_dir));
  if (args.view) written.push_back(write_run_view(args.out_dir));

  std::string no_plots;
  if (args.plot) {
    PlotOutcome plots = plot_results(std::string(handler.name), args.out_dir);
    io::record_plots(args.out_dir, plots.written);
    written.insert(written.end(), plots.written.begin(), plots.written.end());
    if (plots.skipped_because) no_plots = *plots.skipped_because;
  }

  folder.finish();  // a signal during the run: its outputs become .partial (app/output_folder.hpp)
  std::cout << "Wrote:\n";
  for (const auto& path : written) std::cout << "  " << path.string() << '\n';
  std::cout.flush();
  if (!no_plots.empty()) std::cerr << "attiguard: warning: no plots: " << no_plots << '\n';
}

}  // namespace

void run_command(const RunArguments& args) {
  // The folder's earlier outputs go first, even when the scenario is then refused; a failure
  // leaves .partial files and summary.json.partial (docs/conventions.md, "Outputs").
  app::OutputFolder folder(args.out_dir, app::OutputCommand::run, true, {args.scenario});
  app::run_in_folder(folder, {}, args.scenario, [&] { run_into(args, folder); });
}

}  // namespace attiguard::cli
