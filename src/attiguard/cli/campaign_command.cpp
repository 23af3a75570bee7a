/// @file campaign_command.cpp
/// `attiguard campaign`: Monte Carlo runs of a scenario with dispersions, on threads and MPI
/// ranks, with results identical to a serial campaign byte for byte.

#include "attiguard/cli/campaign_command.hpp"

#include "attiguard/cli/campaign_identity.hpp"

#include <unistd.h>

#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "attiguard/app/campaign_run.hpp"
#include "attiguard/app/campaign_runner.hpp"
#include "attiguard/app/outcome_line.hpp"
#include "attiguard/app/output_folder.hpp"
#include "attiguard/cli/commands.hpp"
#include "attiguard/cli/export_aem_command.hpp"
#include "attiguard/cli/output_dir.hpp"
#include "attiguard/cli/view_command.hpp"
#include "attiguard/core/errors.hpp"
#include "attiguard/io/interruption.hpp"
#include "attiguard/parallel/mpi_world.hpp"
#include "attiguard/parallel/thread_limit.hpp"
#include "attiguard/scenario/resolved_scenario.hpp"
#include "attiguard/scenario/work_limits.hpp"

namespace attiguard::cli {

namespace {

/// `--replay K`: run K again with its full trajectory in DIR/run_K; prints its outcome line
/// (docs/conventions.md, "Outcome line": the kind's line, or its status and reason; whether it
/// reproduces its row of runs.csv) and the files written.
void replay(const app::Campaign& c, const CampaignArguments& args, const app::OutputFolder& folder) {
  const long k = *args.replay;
  const std::filesystem::path dir = folder.dir();
  make_output_dir(dir);
  const app::ReplayReport report =
      app::replay_campaign_run(c, k, args.scenario, args.out_dir / "runs.csv", folder);
  const app::RunRecord& r = report.run;
  std::string line = r.status == app::RunStatus::ok
                         ? c.handler->outcome_line(r.summary)
                         : std::string("outcome: ") + app::status_name(r.status) + " (" + r.reason + ")";
  line += "; run " + std::to_string(k) + ", seed " + std::to_string(r.seed);
  if (report.matches_runs_csv) {
    line += *report.matches_runs_csv ? "; identical to its row in runs.csv" : "; DIFFERS from its row in runs.csv";
  }
  std::cout << line << '\n';
  std::cout << "Wrote:\n  " << (dir / "run.csv").string() << '\n';
  for (const char* f : {"trajectory.csv", "summary.json", scenario::kResolvedScenarioFile}) {
    if (std::filesystem::exists(dir / f)) std::cout << "  " << (dir / f).string() << '\n';
  }
  if (args.plot && r.status == app::RunStatus::ok) (void)list_plots(std::string(c.handler->name), dir);
  if (args.aem && r.status == app::RunStatus::ok) {
    std::cout << "  " << write_run_aem(args.scenario, dir).string() << '\n';
  }
  if (args.view && r.status == app::RunStatus::ok) {
    std::cout << "  " << write_run_view(dir).string() << '\n';
  }
  folder.finish();
}

/// The flags' own checks, before anything is read or written.
void check_campaign_arguments(const CampaignArguments& args) {
  parallel::check_thread_count(args.threads);  // 1 to 4 per hardware thread (thread_limit.hpp)
  if ((args.view || args.aem) && !args.replay) {
    throw InputError("--view and --aem go with --replay K (the trajectory of one run); view a "
                     "whole campaign with `attiguard view DIR`");
  }
  if (!args.replay && args.runs < 1) throw InputError("--runs: must be at least 1");
  if (args.replay && *args.replay < 0) throw InputError("--replay: must be a run index >= 0");
  if (const double most = scenario::limit_value(scenario::WorkLimit::campaign_runs);
      !args.replay && static_cast<double>(args.runs) > most) {
    throw InputError("--runs: " + std::to_string(args.runs) + " runs are more than the limit " +
                     CLI::detail::to_string(most) +
                     " (the run list and runs.csv grow with N: a campaign that size does not "
                     "finish or fit); use fewer runs, or raise the limit with --max-runs N");
  }
}

/// The request of `attiguard campaign` (app/campaign_run.hpp): the flags, the identity of this
/// invocation, the progress on stdout and the headline printed when the runs start.
app::CampaignRequest campaign_request(const CampaignArguments& args, const app::Campaign& c,
                                      const parallel::World& world) {
  app::CampaignRequest request;
  request.scenario = args.scenario;
  request.out_dir = args.out_dir;
  request.runs = args.runs;
  request.seed = args.seed;
  request.threads = args.threads;
  request.resume = args.resume;
  request.identity = campaign_identity(args.scenario, args.seed, std::string(c.handler->name));
  request.progress = &std::cout;
  request.progress_bar = ::isatty(STDOUT_FILENO) == 1;
  request.on_start = [&args, &c, &world](const app::CampaignStart& s) {
    std::cout << "Campaign " << args.scenario.string() << " (" << c.handler->name << "): "
              << args.runs << " runs, seed " << args.seed << ", " << s.done
              << " already done, " << s.todo << " to run on " << world.size << " rank(s) x "
              << args.threads << " thread(s)\n"
              << std::flush;
  };
  return request;
}

/// Prints what the campaign wrote (rank 0): its outcome line (docs/conventions.md, "Outcome
/// line"), the interruption, the paths written; writes the envelopes of retained.h5 and the plots.
void report_campaign(const CampaignArguments& args, const app::CampaignReport& report,
                     const app::OutputFolder& folder) {
  std::cout << app::campaign_outcome_line(report.summary) << '\n';
  if (io::interrupted()) {
    // campaign.json becomes campaign.json.partial's "result" (app/output_folder.hpp).
    std::cout << "Interrupted after " << report.wall_time_s << " s: " << report.rows << " of "
              << args.runs << " runs kept in " << report.runs_path.string()
              << "; continue with --resume\n"
              << std::flush;
    folder.finish();
  }
  std::cout << "Wrote:\n  " << report.runs_path.string() << "\n  "
            << report.summary_path.string() << "\n  " << report.resolved_path.string() << '\n';
  if (report.retained_path) {
    app::write_retained_envelopes(*report.retained_path);
    std::cout << "  " << report.retained_path->string() << '\n';
  }
  if (args.plot) print_plots("campaign", args.out_dir);
}

/// The campaign (or the replay) into `folder`.
void campaign_into(const CampaignArguments& args, const parallel::World& world,
                   app::OutputFolder& folder) {
  check_campaign_arguments(args);
  make_output_dir(args.out_dir);
  const app::Campaign c =
      app::load_campaign(args.scenario, args.seed, app::campaign_scratch(args.out_dir, world.rank));
  folder.set_subject(std::string(c.handler->name), args.scenario.string());
  if (args.replay) {
    if (world.root()) replay(c, args, folder);
    return;
  }
  const std::optional<app::CampaignReport> report =
      app::run_campaign(c, campaign_request(args, c, world), world, folder);
  if (!report) return;
  report_campaign(args, *report, folder);
  folder.finish();
}

}  // namespace

void campaign_command(const CampaignArguments& args) {
  // The folder of a campaign (DIR) or of a replay (DIR/run_K): its earlier outputs go first,
  // even when the scenario is then refused — except with --resume, whose folder is its input
  // (app::run_campaign claims it once the identity matches). A failure leaves .partial files and
  // campaign.json.partial / summary.json.partial (docs/conventions.md, "Outputs").
  const parallel::World world = parallel::mpi_world();
  const bool replaying = args.replay && *args.replay >= 0;
  app::OutputFolder folder(replaying ? args.out_dir / ("run_" + std::to_string(*args.replay)) : args.out_dir,
                           replaying ? app::OutputCommand::replay : app::OutputCommand::campaign,
                           world.root() && (replaying || !args.replay), {args.scenario});
  app::run_in_folder(folder, {}, args.scenario, [&] { campaign_into(args, world, folder); },
                     !args.resume || replaying);
}

}  // namespace attiguard::cli
