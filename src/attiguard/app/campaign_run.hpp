#pragma once
/// @file campaign_run.hpp
/// One `attiguard campaign` of a loaded campaign (docs/campaigns.md): the runs of this
/// invocation (those --resume does not keep) split over the MPI ranks and their threads, the
/// rows gathered onto rank 0 and written to DIR/runs.csv sorted, the retained time series in
/// DIR/retained.h5, the identity and the resolved campaign file, and the statistics in
/// DIR/campaign.json — byte for byte the same whatever the ranks and threads (docs/scaling.md).
/// The program (cli/campaign_command.cpp) parses the flags, prints and plots.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <iosfwd>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "attiguard/app/campaign_identity.hpp"
#include "attiguard/app/campaign_runner.hpp"
#include "attiguard/app/output_folder.hpp"
#include "attiguard/parallel/mpi_world.hpp"

namespace attiguard::app {

/// What rank 0 announces once it knows the runs to do, before the first one starts.
struct CampaignStart {
  std::size_t done{0};  ///< rows kept from DIR/runs.csv (--resume)
  std::size_t todo{0};  ///< runs of this invocation, over every rank
};

/// A campaign as asked for on the command line (docs/campaigns.md, "Running a campaign").
struct CampaignRequest {
  std::filesystem::path scenario;  ///< SCENARIO: its file name goes into campaign.json
  std::filesystem::path out_dir;   ///< DIR
  long runs{0};                    ///< --runs N: the runs 0 … N−1
  std::uint64_t seed{1};           ///< --seed S
  int threads{1};                  ///< --threads T per process
  bool resume{false};              ///< --resume: keep the rows of DIR/runs.csv (docs/campaigns.md)
  CampaignIdentity identity;       ///< of this invocation (app/campaign_identity.hpp)
  std::ostream* progress{nullptr}; ///< where rank 0 draws its progress (campaign::Progress); none when null
  bool progress_bar{false};        ///< `progress` is a terminal: the bar redrawn in place
  std::function<void(const CampaignStart&)> on_start;  ///< called on rank 0 when set
};

/// What rank 0 wrote.
struct CampaignReport {
  nlohmann::json summary;          ///< DIR/campaign.json as written
  double wall_time_s{0.0};         ///< of this invocation's runs
  std::size_t rows{0};             ///< rows of DIR/runs.csv
  std::filesystem::path runs_path;      ///< DIR/runs.csv
  std::filesystem::path summary_path;   ///< DIR/campaign.json
  std::filesystem::path resolved_path;  ///< DIR/ the resolved campaign file
  /// DIR/retained.h5 with [campaign] retain (closed; its envelopes not yet written:
  /// write_retained_envelopes).
  std::optional<std::filesystem::path> retained_path;
};

/// DIR/.scratch/rankR: the scratch folder of rank R (its workers' run folders; removed at the end).
[[nodiscard]] std::filesystem::path campaign_scratch(const std::filesystem::path& out_dir, int rank);

/// Runs the campaign `c` (app::load_campaign) as `request` asks (docs/campaigns.md): with
/// --resume checks DIR/campaign_identity.json (InputError naming the difference, the folder
/// unchanged) and claims `folder` keeping its resume state; runs the rest on every rank of
/// `world` (collective), stops picking runs at SIGINT / SIGTERM keeping the rows so far; rank 0
/// writes runs.csv, campaign_identity.json, the resolved campaign, retained.h5 and campaign.json
/// and returns what it wrote; the other ranks return nothing. Throws InputError for [campaign]
/// retain under more than one rank.
[[nodiscard]] std::optional<CampaignReport> run_campaign(const Campaign& c,
                                                         const CampaignRequest& request,
                                                         const parallel::World& world,
                                                         OutputFolder& folder);

/// What `campaign --replay K` produced (replay_campaign_run).
struct ReplayReport {
  RunRecord run;    ///< run K (status, reason, seed, summary)
  std::string row;  ///< its runs.csv line, as written to DIR/run_K/run.csv
  /// Whether `row` is the line of run K in DIR/runs.csv; nothing when runs.csv has no run K.
  std::optional<bool> matches_runs_csv;
};

/// `campaign --replay K` (docs/campaigns.md, "Replaying a run"): runs run `k` of `c` again with
/// its files (trajectory.csv, summary.json) in `folder`'s directory (which must exist), then
/// writes there the dispersed scenario of the run with every default filled in (none when every
/// draw was rejected) and run.csv (the header and its row), and compares the row with run K of
/// `runs_csv` (campaign::read_runs: InputError when that file's header differs). A signal during
/// the run ends it with io::Interrupted before anything else is written (OutputFolder::finish).
[[nodiscard]] ReplayReport replay_campaign_run(const Campaign& c, long k,
                                               const std::filesystem::path& scenario,
                                               const std::filesystem::path& runs_csv,
                                               const OutputFolder& folder);

/// Writes the percentile envelopes and worst runs of every column of a closed retained.h5
/// (campaign::envelope, campaign::write_envelopes; docs/campaigns.md, "Retained time series").
void write_retained_envelopes(const std::filesystem::path& retained_h5);

}  // namespace attiguard::app
