/// @file campaign_command.cpp
/// `attiguard campaign`: Monte Carlo runs of a scenario with dispersions, on threads and MPI
/// ranks, with results identical to a serial campaign byte for byte.

#include "attiguard/cli/campaign_command.hpp"

#include "attiguard/cli/campaign_identity.hpp"

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>

#include <CLI/CLI.hpp>
#include <string>

#include "attiguard/campaign/aggregation.hpp"
#include "attiguard/campaign/csv_format.hpp"
#include "attiguard/campaign/envelopes.hpp"
#include "attiguard/campaign/retained_file.hpp"
#include "attiguard/campaign/row_gather.hpp"
#include "attiguard/campaign/progress.hpp"
#include "attiguard/app/campaign_runner.hpp"
#include "attiguard/app/outcome_line.hpp"
#include "attiguard/campaign/runs_file.hpp"
#include "attiguard/cli/commands.hpp"
#include "attiguard/cli/output_dir.hpp"
#include "attiguard/cli/export_aem_command.hpp"
#include "attiguard/cli/view_command.hpp"
#include "attiguard/core/errors.hpp"
#include "attiguard/app/output_folder.hpp"
#include "attiguard/io/interruption.hpp"
#include "attiguard/io/output_records.hpp"
#include "attiguard/parallel/thread_limit.hpp"
#include "attiguard/scenario/resolved_scenario.hpp"
#include "attiguard/scenario/work_limits.hpp"

namespace attiguard::cli {

namespace {

std::string join(const std::vector<std::string>& cols) {
  std::string s;
  for (const auto& c : cols) s += (s.empty() ? "" : ",") + c;
  return s;
}

/// `--replay K`: run K again with its full trajectory in DIR/run_K.
void replay(const app::Campaign& c, const CampaignArguments& args, const app::OutputFolder& folder) {
  const long k = *args.replay;
  const std::filesystem::path dir = folder.dir();
  make_output_dir(dir);
  app::RunOptions options;
  options.out_dir = dir;
  options.write_files = true;
  scenario::Document drawn;
  const app::RunRecord r = app::run_one(c, k, options, &drawn);
  folder.finish();  // a signal during the run: not a row of the campaign
  // The dispersed scenario of run K, every default filled in: `attiguard run` of it flies this
  // run again (docs/conventions.md, "Outputs"); none for a run whose every draw was rejected.
  if (r.status != app::RunStatus::rejected) {
    io::write_text(dir, scenario::kResolvedScenarioFile,
                   scenario::resolve_scenario(drawn, c.handler->check,
                                              "run " + std::to_string(k) + " (seed " +
                                                  std::to_string(r.seed) + ") of " +
                                                  args.scenario.string()));
  }
  const std::string header = join(app::csv_columns(c));
  const std::string row = app::csv_row(c, r);
  io::write_text(dir, "run.csv", header + '\n' + row + '\n');
  // The one-line outcome of the replayed run (docs/conventions.md, "Outcome line"): the kind's
  // line, or its status and reason; whether it reproduces its row of runs.csv.
  std::string line = r.status == app::RunStatus::ok
                         ? c.handler->outcome_line(r.summary)
                         : std::string("outcome: ") + app::status_name(r.status) + " (" + r.reason + ")";
  line += "; run " + std::to_string(k) + ", seed " + std::to_string(r.seed);
  const auto existing = campaign::read_runs(args.out_dir / "runs.csv", header);
  if (const auto it = existing.find(k); it != existing.end()) {
    line += it->second == row ? "; identical to its row in runs.csv" : "; DIFFERS from its row in runs.csv";
  }
  std::cout << line << '\n';
  std::cout << "Wrote:\n  " << (dir / "run.csv").string() << '\n';
  for (const char* f : {"trajectory.csv", "summary.json", scenario::kResolvedScenarioFile}) {
    if (std::filesystem::exists(dir / f)) std::cout << "  " << (dir / f).string() << '\n';
  }
  if (args.plot && r.status == app::RunStatus::ok) {
    const PlotOutcome p = plot_results(std::string(c.handler->name), dir);
    io::record_plots(dir, p.written);
    for (const auto& w : p.written) std::cout << "  " << w.string() << '\n';
  }
  if (args.aem && r.status == app::RunStatus::ok) {
    std::cout << "  " << write_run_aem(args.scenario, dir).string() << '\n';
  }
  if (args.view && r.status == app::RunStatus::ok) {
    std::cout << "  " << write_run_view(dir).string() << '\n';
  }
  folder.finish();
}

/// The campaign (or the replay) into `folder`.
void campaign_into(const CampaignArguments& args, const parallel::World& world,
                   app::OutputFolder& folder) {
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
  make_output_dir(args.out_dir);
  const std::filesystem::path scratch =
      args.out_dir / ".scratch" / ("rank" + std::to_string(world.rank));
  const app::Campaign c = app::load_campaign(args.scenario, args.seed, scratch);
  folder.set_subject(std::string(c.handler->name), args.scenario.string());
  if (args.replay) {
    if (world.root()) replay(c, args, folder);
    return;
  }

  const std::string header = join(app::csv_columns(c));
  const std::filesystem::path runs_path = args.out_dir / "runs.csv";
  const std::filesystem::path identity_path = args.out_dir / "campaign_identity.json";
  const CampaignIdentity identity =
      campaign_identity(args.scenario, args.seed, std::string(c.handler->name));
  std::map<long, std::string> done;
  if (args.resume) {
    const std::map<long, std::string> previous = campaign::read_runs(runs_path, header);
    check_resume_identity(identity_path, identity, previous.size());
    for (const auto& [k, line] : previous) {
      if (k < args.runs) done.emplace(k, line);
    }
    // The folder is this campaign's: what it resumes from stays, the rest goes
    // (app/output_folder.hpp). A refused --resume changed nothing.
    app::Keep keep;
    keep.names = {"runs.csv", "campaign_identity.json", "retained.h5", scenario::kResolvedScenarioFile};
    keep.replays = true;
    folder.claim(keep);
  }
  parallel::barrier(world);
  std::vector<long> todo;
  for (long k = 0; k < args.runs; ++k) {
    if (!done.contains(k)) todo.push_back(k);
  }
  const std::vector<long> share = parallel::rank_share(todo, world);

  std::optional<campaign::RunsAppender> appender;
  if (world.root()) {
    write_identity(identity_path, identity);
    // The campaign file with its constant defaults filled in: `attiguard campaign` of it with
    // the same --runs and --seed gives the same runs.csv (docs/conventions.md, "Outputs").
    io::write_text(args.out_dir, scenario::kResolvedScenarioFile,
                   scenario::resolve_campaign(scenario::load_document(args.scenario), c.handler->check));
    if (args.resume && !done.empty()) campaign::write_sorted(runs_path, header, done);
    appender.emplace(runs_path, header);
    std::cout << "Campaign " << args.scenario.string() << " (" << c.handler->name << "): "
              << args.runs << " runs, seed " << args.seed << ", " << done.size()
              << " already done, " << todo.size() << " to run on " << world.size << " rank(s) x "
              << args.threads << " thread(s)\n"
              << std::flush;
  }

  const auto start = std::chrono::steady_clock::now();
  campaign::Progress progress(std::cout, static_cast<long>(share.size()),
                              world.root() && ::isatty(STDOUT_FILENO) == 1);
  // [campaign] retain: the retained time series of every run in DIR/retained.h5 (one process).
  std::optional<campaign::RetainedFile> retained;
  if (c.plan.retain.enabled()) {
    if (world.size > 1) {
      throw InputError(args.scenario.string() + ": [campaign] retain is written by one process: run "
                       "this campaign without mpirun (use --threads)");
    }
    retained.emplace(args.out_dir / "retained.h5", c.plan.retain.columns, c.retain_times,
                     static_cast<std::size_t>(args.runs), c.plan.retain.interval, args.resume);
  }
  std::map<long, std::string> mine;
  // SIGINT / SIGTERM: the workers finish their current run and pick no new one
  // (io/interruption.hpp); the rows so far are kept.
  app::run_many(c, share, args.threads, scratch, io::interruption_flag(), [&](const app::RunRecord& r) {
    if (retained && r.status == app::RunStatus::ok) {
      retained->write_run(static_cast<std::size_t>(r.index), r.retained, r.retained_samples);
    }
    std::string row = app::csv_row(c, r);
    if (appender) appender->append(row);
    mine.emplace(r.index, std::move(row));
    if (world.root()) progress.tick();
  });
  progress.finish();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::map<long, std::string> gathered = campaign::gather_rows(mine, world);
  std::error_code ec;
  std::filesystem::remove_all(scratch, ec);
  if (!world.root()) return;
  for (auto& [k, line] : gathered) done.insert_or_assign(k, std::move(line));
  appender.reset();
  campaign::write_sorted(runs_path, header, done);

  campaign::CampaignInfo info;
  info.scenario = args.scenario.filename().string();
  info.kind = std::string(c.handler->name);
  info.seed = args.seed;
  info.runs = args.runs;
  info.max_attempts = c.plan.max_attempts;
  for (const auto& d : c.plan.items) info.dispersed.push_back(d.key);
  nlohmann::json summary = campaign::aggregate(info, campaign::csv_split(header), done);
  summary["scenario_sha256"] = identity.scenario_sha256;
  summary["attiguard_version"] = identity.version;
  io::write_text(args.out_dir, "campaign.json", summary.dump(2) + '\n');
  std::filesystem::remove(args.out_dir / ".scratch", ec);

  // The one-line outcome (docs/conventions.md, "Outcome line"), then the paths written.
  std::cout << app::campaign_outcome_line(summary) << '\n';
  if (io::interrupted()) {
    // campaign.json becomes campaign.json.partial's "result" (app/output_folder.hpp).
    std::cout << "Interrupted after " << wall << " s: " << done.size() << " of " << args.runs
              << " runs kept in " << runs_path.string() << "; continue with --resume\n"
              << std::flush;
    folder.finish();
  }
  std::cout << "Wrote:\n  " << runs_path.string() << "\n  "
            << (args.out_dir / "campaign.json").string() << "\n  "
            << (args.out_dir / scenario::kResolvedScenarioFile).string() << '\n';
  if (retained) {
    retained.reset();  // closes the file
    const auto path = args.out_dir / "retained.h5";
    const campaign::RetainedSeries series = campaign::read_retained(path);
    std::vector<campaign::Envelope> envelopes;
    for (std::size_t col = 0; col < series.columns.size(); ++col) envelopes.push_back(campaign::envelope(series, col));
    campaign::write_envelopes(path, envelopes);
    std::cout << "  " << path.string() << '\n';
  }
  if (args.plot) {
    const PlotOutcome p = plot_results("campaign", args.out_dir);
    io::record_plots(args.out_dir, p.written);
    for (const auto& w : p.written) std::cout << "  " << w.string() << '\n';
    if (p.skipped_because) std::cerr << "attiguard: warning: no plots: " << *p.skipped_because << '\n';
  }
  folder.finish();
}

}  // namespace

void campaign_command(const CampaignArguments& args) {
  // The folder of a campaign (DIR) or of a replay (DIR/run_K): its earlier outputs go first,
  // even when the scenario is then refused — except with --resume, whose folder is its input
  // (campaign_into claims it once the identity matches). A failure leaves .partial files and
  // campaign.json.partial / summary.json.partial (docs/conventions.md, "Outputs").
  const parallel::World world = parallel::mpi_world();
  const bool replaying = args.replay && *args.replay >= 0;
  app::OutputFolder folder(replaying ? args.out_dir / ("run_" + std::to_string(*args.replay)) : args.out_dir,
                           replaying ? app::OutputCommand::replay : app::OutputCommand::campaign,
                           world.root() && (replaying || !args.replay), {args.scenario});
  if (!args.resume || replaying) folder.claim();
  folder.set_subject({}, args.scenario.string());
  try {
    campaign_into(args, world, folder);
  } catch (...) {
    folder.fail(std::current_exception());
  }
}

}  // namespace attiguard::cli
