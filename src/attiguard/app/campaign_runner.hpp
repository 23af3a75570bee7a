#pragma once
/// @file campaign_runner.hpp
/// One campaign: the scenario, its dispersions, and the execution of run k (draw, validate with
/// the kind's own check, run in memory, reduce the summary to one CSV row).

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "attiguard/app/kinds.hpp"
#include "attiguard/core/name_table.hpp"
#include "attiguard/scenario/dispersion.hpp"
#include "attiguard/scenario/document.hpp"

namespace attiguard::app {

/// A loaded campaign scenario.
struct Campaign {
  scenario::Document nominal;   ///< the scenario without [dispersions] / [campaign]
  scenario::DispersionPlan plan;
  const KindHandler* handler{nullptr};
  std::uint64_t seed{0};
  /// Summary figures recorded per run (numeric and boolean top-level keys of the nominal run's
  /// summary, sorted, without wall_time_s and output_rows).
  std::vector<std::string> figures;
  /// t_k of the retained samples of the nominal run (plan.retain; docs/campaigns.md).
  std::vector<double> retain_times;
  /// The nominal summary has a string `outcome` (docs/campaigns.md): runs.csv gets its column.
  bool outcome_column{false};
};

/// Outcome of one run.
enum class RunStatus { ok, rejected, failed };
/// The names of the statuses in runs.csv's `status` column (docs/campaigns.md, "Outputs").
inline constexpr NameTable<RunStatus, 3> kRunStatusNames{
    {{{RunStatus::ok, "ok"}, {RunStatus::rejected, "rejected"}, {RunStatus::failed, "failed"}}}};
/// The name of `s` in kRunStatusNames.
[[nodiscard]] const char* status_name(RunStatus s) noexcept;

/// One run of a campaign.
struct RunRecord {
  long index{0};
  std::uint64_t seed{0};
  long attempts{0};                ///< draws made (> 1 when inadmissible draws were resampled)
  RunStatus status{RunStatus::ok};
  std::string reason;              ///< why rejected / failed (one line)
  std::vector<double> values;      ///< dispersed values (dispersion_columns order)
  nlohmann::json summary;          ///< the kind's summary (null unless ok)
  bool violation{false};           ///< a "*_satisfied" summary flag is false
  std::vector<double> retained;    ///< retained columns, column-major (campaign::RetainSink)
  std::size_t retained_samples{0}; ///< samples per retained column
};

/// Loads the scenario file, reads its dispersions, checks the nominal scenario with its kind, and
/// runs it once (in `scratch`) to learn the summary figures. Throws InputError (the kind must
/// be a `run` kind), NumericalError when the nominal run fails.
[[nodiscard]] Campaign load_campaign(const std::filesystem::path& path, std::uint64_t seed,
                                     const std::filesystem::path& scratch);

/// The dispersed scenario of run k after `attempt` draws: draws are taken from one stream
/// seeded with run_seed(seed, k), so attempt a is reproducible. `values` receives the values.
[[nodiscard]] scenario::Document dispersed_document(const Campaign& c, campaign::Rng& rng,
                                                    std::vector<double>& values);

/// Runs run k: draws until the kind's check accepts the scenario (at most plan.max_attempts,
/// then status rejected), runs it (exceptions, NaN in the summary: status failed). Never
/// throws for a problem of the run itself. With options.write_files the run writes its
/// trajectory.csv/summary.json into options.out_dir (replay). `drawn`, when given, receives the
/// dispersed scenario of the run (the last draw; the replay resolves it).
[[nodiscard]] RunRecord run_one(const Campaign& c, long k, const RunOptions& options,
                                scenario::Document* drawn = nullptr);

/// Header of runs.csv.
[[nodiscard]] std::vector<std::string> csv_columns(const Campaign& c);
/// The header line of runs.csv: csv_columns joined by commas (no newline).
[[nodiscard]] std::string csv_header(const Campaign& c);
/// One runs.csv line (no newline), numbers printed with %.17g (exact, locale-independent).
[[nodiscard]] std::string csv_row(const Campaign& c, const RunRecord& r);

/// Runs the given run indices on `threads` workers (≥ 1); `on_done` is called (serialised under
/// a mutex) as each run finishes. Stops picking new runs once `stop` becomes true.
void run_many(const Campaign& c, const std::vector<long>& indices, int threads,
              const std::filesystem::path& scratch, const std::atomic<bool>& stop,
              const std::function<void(const RunRecord&)>& on_done);

}  // namespace attiguard::app
