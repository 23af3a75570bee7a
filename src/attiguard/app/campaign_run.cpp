/// @file campaign_run.cpp
/// One campaign of a loaded scenario (app/campaign_run.hpp, docs/campaigns.md).

#include "attiguard/app/campaign_run.hpp"

#include <chrono>
#include <map>
#include <ostream>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "attiguard/campaign/aggregation.hpp"
#include "attiguard/campaign/csv_format.hpp"
#include "attiguard/campaign/envelopes.hpp"
#include "attiguard/campaign/progress.hpp"
#include "attiguard/campaign/retained_file.hpp"
#include "attiguard/campaign/row_gather.hpp"
#include "attiguard/campaign/runs_file.hpp"
#include "attiguard/core/errors.hpp"
#include "attiguard/io/interruption.hpp"
#include "attiguard/io/json_file.hpp"
#include "attiguard/io/output_records.hpp"
#include "attiguard/scenario/resolved_scenario.hpp"

namespace attiguard::app {

namespace {

namespace fs = std::filesystem;
using Rows = std::map<long, std::string>;  ///< run index → its runs.csv line (no newline)

constexpr const char* kRunsFile = "runs.csv";
constexpr const char* kIdentityFile = "campaign_identity.json";
constexpr const char* kRetainedFile = "retained.h5";
constexpr const char* kSummaryFile = "campaign.json";

/// --resume: the rows of DIR/runs.csv below --runs, once the identity matches; then the folder
/// is this campaign's: what it resumes from stays, the rest goes (app/output_folder.hpp). A
/// refused --resume changed nothing. Without --resume: no rows.
Rows resumed_rows(const CampaignRequest& r, const std::string& header, OutputFolder& folder) {
  Rows done;
  if (!r.resume) return done;
  const Rows previous = campaign::read_runs(r.out_dir / kRunsFile, header);
  check_resume_identity(r.out_dir / kIdentityFile, r.identity, previous.size());
  for (const auto& [k, line] : previous) {
    if (k < r.runs) done.emplace(k, line);
  }
  Keep keep;
  keep.names = {kRunsFile, kIdentityFile, kRetainedFile, scenario::kResolvedScenarioFile};
  keep.replays = true;
  folder.claim(keep);
  return done;
}

/// The runs 0 … runs−1 not in `done`, in order.
std::vector<long> runs_to_do(long runs, const Rows& done) {
  std::vector<long> todo;
  for (long k = 0; k < runs; ++k) {
    if (!done.contains(k)) todo.push_back(k);
  }
  return todo;
}

/// Rank 0's first files: the identity, the campaign file with its constant defaults filled in
/// (`attiguard campaign` of it with the same --runs and --seed gives the same runs.csv;
/// docs/conventions.md, "Outputs"), runs.csv of the resumed rows; then the appender of the new rows.
campaign::RunsAppender begin_outputs(const Campaign& c, const CampaignRequest& r,
                                     const std::string& header, const Rows& done) {
  write_identity(r.out_dir / kIdentityFile, r.identity);
  io::write_text(r.out_dir, scenario::kResolvedScenarioFile,
                 scenario::resolve_campaign(scenario::load_document(r.scenario), c.handler->check));
  if (r.resume && !done.empty()) campaign::write_sorted(r.out_dir / kRunsFile, header, done);
  return campaign::RunsAppender(r.out_dir / kRunsFile, header);
}

/// [campaign] retain: the retained time series of every run in DIR/retained.h5, written by one
/// process (docs/campaigns.md, "Retained time series"), opened into `retained`; none without
/// retain.
void open_retained(const Campaign& c, const CampaignRequest& r, const parallel::World& world,
                   std::optional<campaign::RetainedFile>& retained) {
  if (!c.plan.retain.enabled()) return;
  if (world.size > 1) {
    throw InputError(r.scenario.string() + ": [campaign] retain is written by one process: run "
                     "this campaign without mpirun (use --threads)");
  }
  retained.emplace(r.out_dir / kRetainedFile, c.plan.retain.columns, c.retain_times,
                   static_cast<std::size_t>(r.runs), c.plan.retain.interval, r.resume);
}

/// Runs this rank's `share` on its threads: each row goes to runs.csv (rank 0), to the retained
/// file and into the returned rows. SIGINT / SIGTERM: the workers finish their current run and
/// pick no new one (io/interruption.hpp); the rows so far are kept.
Rows run_share(const Campaign& c, const CampaignRequest& r, const std::vector<long>& share,
               const parallel::World& world, campaign::RunsAppender* appender,
               std::optional<campaign::RetainedFile>& retained, campaign::Progress& progress) {
  Rows mine;
  run_many(c, share, r.threads, campaign_scratch(r.out_dir, world.rank), io::interruption_flag(),
           [&](const RunRecord& run) {
             if (retained && run.status == RunStatus::ok) {
               retained->write_run(static_cast<std::size_t>(run.index), run.retained,
                                   run.retained_samples);
             }
             std::string row = csv_row(c, run);
             if (appender) appender->append(row);
             mine.emplace(run.index, std::move(row));
             if (world.root()) progress.tick();
           });
  progress.finish();
  return mine;
}

/// campaign.json: the statistics of every row (campaign::aggregate) with the identity's digest
/// and version (docs/campaigns.md, "Outputs").
nlohmann::json campaign_summary(const Campaign& c, const CampaignRequest& r,
                                const std::string& header, const Rows& done) {
  campaign::CampaignInfo info;
  info.scenario = r.scenario.filename().string();
  info.kind = std::string(c.handler->name);
  info.seed = r.seed;
  info.runs = r.runs;
  info.max_attempts = c.plan.max_attempts;
  for (const auto& d : c.plan.items) info.dispersed.push_back(d.key);
  nlohmann::json summary = campaign::aggregate(info, campaign::csv_split(header), done);
  summary["scenario_sha256"] = r.identity.scenario_sha256;
  summary["attiguard_version"] = r.identity.version;
  return summary;
}

/// Rank 0's last files: runs.csv of every row sorted, campaign.json; the report.
CampaignReport end_outputs(const Campaign& c, const CampaignRequest& r, const std::string& header,
                           const Rows& done) {
  CampaignReport report;
  report.runs_path = r.out_dir / kRunsFile;
  report.summary_path = r.out_dir / kSummaryFile;
  report.resolved_path = r.out_dir / scenario::kResolvedScenarioFile;
  report.rows = done.size();
  campaign::write_sorted(report.runs_path, header, done);
  report.summary = campaign_summary(c, r, header, done);
  io::write_json(report.summary_path, report.summary);
  if (c.plan.retain.enabled()) report.retained_path = r.out_dir / kRetainedFile;
  return report;
}

}  // namespace

fs::path campaign_scratch(const fs::path& out_dir, int rank) {
  return out_dir / ".scratch" / ("rank" + std::to_string(rank));
}

std::optional<CampaignReport> run_campaign(const Campaign& c, const CampaignRequest& request,
                                           const parallel::World& world, OutputFolder& folder) {
  const std::string header = csv_header(c);
  Rows done = resumed_rows(request, header, folder);
  parallel::barrier(world);
  const std::vector<long> todo = runs_to_do(request.runs, done);
  const std::vector<long> share = parallel::rank_share(todo, world);
  std::optional<campaign::RunsAppender> appender;
  if (world.root()) {
    appender.emplace(begin_outputs(c, request, header, done));
    if (request.on_start) request.on_start({done.size(), todo.size()});
  }
  const auto start = std::chrono::steady_clock::now();
  std::ostream null_out(nullptr);
  campaign::Progress progress(request.progress != nullptr ? *request.progress : null_out,
                              static_cast<long>(share.size()),
                              world.root() && request.progress_bar);
  std::optional<campaign::RetainedFile> retained;
  open_retained(c, request, world, retained);
  const Rows mine = run_share(c, request, share, world, appender ? &*appender : nullptr,
                              retained, progress);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  Rows gathered = campaign::gather_rows(mine, world);
  std::error_code ec;
  fs::remove_all(campaign_scratch(request.out_dir, world.rank), ec);
  if (!world.root()) return std::nullopt;
  for (auto& [k, line] : gathered) done.insert_or_assign(k, std::move(line));
  appender.reset();
  retained.reset();  // closes the file
  CampaignReport report = end_outputs(c, request, header, done);
  report.wall_time_s = wall;
  fs::remove(request.out_dir / ".scratch", ec);
  return report;
}

ReplayReport replay_campaign_run(const Campaign& c, long k, const fs::path& scenario,
                                 const fs::path& runs_csv, const OutputFolder& folder) {
  const fs::path dir = folder.dir();
  RunOptions options;
  options.out_dir = dir;
  options.write_files = true;
  scenario::Document drawn;
  ReplayReport report;
  report.run = run_one(c, k, options, &drawn);
  const RunRecord& r = report.run;
  folder.finish();  // a signal during the run: not a row of the campaign
  // The dispersed scenario of run K, every default filled in: `attiguard run` of it flies this
  // run again (docs/conventions.md, "Outputs"); none for a run whose every draw was rejected.
  if (r.status != RunStatus::rejected) {
    io::write_text(dir, scenario::kResolvedScenarioFile,
                   scenario::resolve_scenario(drawn, c.handler->check,
                                              "run " + std::to_string(k) + " (seed " +
                                                  std::to_string(r.seed) + ") of " +
                                                  scenario.string()));
  }
  const std::string header = csv_header(c);
  report.row = csv_row(c, r);
  io::write_text(dir, "run.csv", header + '\n' + report.row + '\n');
  const Rows existing = campaign::read_runs(runs_csv, header);
  if (const auto it = existing.find(k); it != existing.end()) {
    report.matches_runs_csv = it->second == report.row;
  }
  return report;
}

void write_retained_envelopes(const fs::path& retained_h5) {
  const campaign::RetainedSeries series = campaign::read_retained(retained_h5);
  std::vector<campaign::Envelope> envelopes;
  for (std::size_t col = 0; col < series.columns.size(); ++col) {
    envelopes.push_back(campaign::envelope(series, col));
  }
  campaign::write_envelopes(retained_h5, envelopes);
}

}  // namespace attiguard::app
