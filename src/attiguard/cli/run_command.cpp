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
#include "attiguard/io/output_records.hpp"

namespace attiguard::cli {

void run_command(const RunArguments& args) {
  const scenario::Document doc = scenario::load_document(args.scenario);
  if (doc.has_top_level("dispersions")) {  // a campaign scenario (docs/campaigns.md)
    throw InputError(args.scenario.string() +
                     ": a campaign scenario ([dispersions]): run it with `attiguard campaign " +
                     args.scenario.string() + " --runs N --out DIR`, or one of its runs with "
                     "`--replay K`");
  }
  const app::KindHandler& handler = app::handler_for(doc);
  make_output_dir(args.out_dir);

  app::RunOptions options;
  options.out_dir = args.out_dir;
  io::remove_recorded_plots(args.out_dir);  // an earlier run's figures, maybe of another kind
  // What this run is computed from, every default filled in (scenario/resolved_scenario.hpp).
  io::write_text(args.out_dir, scenario::kResolvedScenarioFile, scenario::resolve_scenario(doc, handler.check));
  const nlohmann::json summary = [&] {
    // A failure leaves summary.json.partial saying so beside trajectory.csv.partial.
    const auto mark_partial = [&](const Error& e) {
      io::write_failure_status(args.out_dir, "summary.json", std::string(handler.name),
                               args.scenario.string(), static_cast<int>(e.code()), e.what());
    };
    try {
      return handler.run(doc, options);
    } catch (const NumericalError& e) {  // name the key most likely responsible (app/failure.hpp)
      const NumericalError located(app::located_numerical_failure(e.what(), doc));
      mark_partial(located);
      throw located;
    } catch (const Error& e) {
      mark_partial(e);
      throw;
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

  std::cout << "Wrote:\n";
  for (const auto& path : written) std::cout << "  " << path.string() << '\n';
  std::cout.flush();
  if (!no_plots.empty()) std::cerr << "attiguard: warning: no plots: " << no_plots << '\n';
}

}  // namespace attiguard::cli
