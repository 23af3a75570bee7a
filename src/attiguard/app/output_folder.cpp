/// @file output_folder.cpp
/// The output-folder contract (app/output_folder.hpp, docs/conventions.md "Outputs").

#include "attiguard/app/output_folder.hpp"

#include <algorithm>
#include <array>
#include <fstream>
#include <system_error>
#include <utility>

#include <nlohmann/json.hpp>

#include "attiguard/app/failure.hpp"
#include "attiguard/core/name_table.hpp"
#include "attiguard/io/interruption.hpp"
#include "attiguard/io/output_records.hpp"
#include "attiguard/io/partial_file.hpp"
#include "attiguard/scenario/document_edit.hpp"
#include "attiguard/scenario/resolved_scenario.hpp"

namespace attiguard::app {

namespace {

namespace fs = std::filesystem;

constexpr const char* kScratch = ".scratch";  ///< campaign and tune workers' scratch folders
constexpr const char* kPlotList = "plots.txt";  ///< io/output_records.hpp: the figures written

/// The commands in OutputCommand order (the index of their tables).
constexpr std::size_t kCommands = 8;

constexpr std::size_t command_index(OutputCommand c) { return static_cast<std::size_t>(c); }

/// The per-command tables, built once (two names come from scenario/).
struct Tables {
  std::array<std::vector<std::string>, kCommands> of;  ///< output_names(), by command_index
  std::vector<std::string> known;
  Tables() {
    const std::string resolved = scenario::kResolvedScenarioFile;
    of[command_index(OutputCommand::run)] = {"trajectory.csv", "summary.json", resolved,
                                             "attitude.aem",   "view.html",    kPlotList};
    of[command_index(OutputCommand::reach)] = {
        "reach.json", "trajectory.csv", "steps.csv", "tube.csv",  "boundary.csv",
        "samples.csv", resolved,        "view.html", kPlotList};
    of[command_index(OutputCommand::campaign)] = {
        "runs.csv", "campaign.json", "campaign_identity.json", "retained.h5", resolved, kPlotList};
    of[command_index(OutputCommand::replay)] = {"run.csv",      "trajectory.csv", "summary.json",
                                                resolved,       "attitude.aem",   "view.html",
                                                kPlotList};
    of[command_index(OutputCommand::tune)] = {"tune.json", scenario::scenario_file_name("best"),
                                              kPlotList};
    of[command_index(OutputCommand::view)] = {"view.html"};
    of[command_index(OutputCommand::export_aem)] = {"attitude.aem"};
    of[command_index(OutputCommand::plan)] = {"plan.csv", "plan.json", resolved, kPlotList};
    for (const std::vector<std::string>& set : of) {
      for (const std::string& n : set) {
        if (std::find(known.begin(), known.end(), n) == known.end()) known.push_back(n);
      }
    }
  }
};

/// The status file of each command (status_name()); "" for view and export-aem.
constexpr NameTable<OutputCommand, kCommands> kStatusFiles{{{
    {OutputCommand::run, "summary.json"},
    {OutputCommand::reach, "reach.json"},
    {OutputCommand::campaign, "campaign.json"},
    {OutputCommand::replay, "summary.json"},
    {OutputCommand::tune, "tune.json"},
    {OutputCommand::view, ""},
    {OutputCommand::export_aem, ""},
    {OutputCommand::plan, "plan.json"},
}}};

const Tables& tables() {
  static const Tables t;
  return t;
}

/// The command writes into a folder of its own (not into the folder of results it reads).
bool claims_folder(OutputCommand c) {
  return c != OutputCommand::view && c != OutputCommand::export_aem;
}

/// Kept when a campaign fails: what --resume continues from (docs/campaigns.md).
bool resume_state(OutputCommand c, const std::string& name) {
  return c == OutputCommand::campaign &&
         (name == "runs.csv" || name == "campaign_identity.json" || name == "retained.h5");
}

void remove_file(const fs::path& path) {
  std::error_code ec;
  fs::remove(path, ec);
}

/// `path` as compared with the inputs of a command.
fs::path canonical_form(const fs::path& path) {
  std::error_code ec;
  fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec);
  return ec ? path.lexically_normal() : p;
}

bool is_input(const fs::path& path, const std::vector<fs::path>& inputs) {
  if (inputs.empty()) return false;
  return std::find(inputs.begin(), inputs.end(), canonical_form(path)) != inputs.end();
}

/// Removes NAME and NAME.partial for each of `names` in `dir` except those in `keep` and the
/// command's inputs, and the figures recorded in plots.txt when plots.txt is one of them.
void remove_known(const fs::path& dir, std::span<const std::string> names,
                  const std::vector<std::string>& keep, const std::vector<fs::path>& inputs) {
  const auto listed = [](const auto& list, const std::string& n) {
    return std::find(list.begin(), list.end(), n) != list.end();
  };
  if (listed(names, kPlotList) && !listed(keep, kPlotList)) io::remove_recorded_plots(dir);
  for (const std::string& n : names) {
    if (std::find(keep.begin(), keep.end(), n) != keep.end() || is_input(dir / n, inputs)) continue;
    remove_file(dir / n);
    remove_file(io::partial_path(dir / n));
  }
}

/// run_K: a folder a replay writes (campaign --replay K).
bool is_replay_folder(const fs::directory_entry& entry) {
  std::error_code ec;
  if (!entry.is_directory(ec)) return false;
  const std::string n = entry.path().filename().string();
  return n.size() > 4 && n.starts_with("run_") &&
         std::all_of(n.begin() + 4, n.end(), [](char ch) { return ch >= '0' && ch <= '9'; });
}

}  // namespace

std::span<const std::string> output_names(OutputCommand command) {
  const std::size_t i = command_index(command);
  return i < kCommands ? std::span<const std::string>(tables().of[i]) : std::span<const std::string>();
}

std::span<const std::string> known_output_names() { return tables().known; }

std::string status_name(OutputCommand command) {
  const std::string_view name = kStatusFiles.name(command);
  return name == "?" ? std::string() : std::string(name);
}

OutputFolder::OutputFolder(fs::path dir, OutputCommand command, bool active,
                           const std::vector<fs::path>& inputs)
    : dir_(std::move(dir)), command_(command), active_(active) {
  for (const fs::path& input : inputs) {
    if (!input.empty()) inputs_.push_back(canonical_form(input));
  }
}

void OutputFolder::claim(const Keep& keep) {
  std::error_code ec;
  if (!active_) return;
  claimed_ = true;
  if (dir_.empty() || !fs::is_directory(dir_, ec)) return;
  if (!claims_folder(command_)) {
    remove_known(dir_, output_names(command_), keep.names, inputs_);
    return;
  }
  remove_known(dir_, known_output_names(), keep.names, inputs_);
  fs::remove_all(dir_ / kScratch, ec);
  if (keep.replays) return;
  std::vector<fs::path> replays;
  for (const auto& entry : fs::directory_iterator(dir_, ec)) {
    if (is_replay_folder(entry)) replays.push_back(entry.path());
  }
  for (const fs::path& r : replays) {
    remove_known(r, known_output_names(), {}, inputs_);
    fs::remove(r, ec);  // only when nothing else is left in it
  }
}

void OutputFolder::set_subject(std::string kind, std::string scenario) {
  kind_ = std::move(kind);
  scenario_ = std::move(scenario);
}

void OutputFolder::finish() const {
  io::throw_if_interrupted();
}

void OutputFolder::fail(const std::exception_ptr& error) const {
  const bool signalled = io::interrupted();
  Failure f = describe_failure(error, scenario_);
  std::error_code ec;
  if (!active_ || !claimed_ || (f.code == ExitCode::verification_failed && !signalled) ||
      !fs::is_directory(dir_, ec)) {
    std::rethrow_exception(error);
  }
  const std::string status = status_name(command_);
  if (signalled) {
    f.code = ExitCode::numerical_failure;
    f.message = "interrupted by " + io::interruption_signal_name() + ": ";
    if (status.empty()) {
      f.message += "no " + (dir_ / output_names(command_).front()).string() + " written";
    } else {
      f.message += dir_.string() + " holds only partial outputs (NAME.partial) and the status " +
                   io::partial_path(dir_ / status).string();
      if (command_ == OutputCommand::campaign) {
        f.message += "; runs.csv keeps the finished runs: continue with --resume";
      }
    }
  }
  nlohmann::json result = nullptr;
  for (const std::string& n : output_names(command_)) {
    if (n == kPlotList || resume_state(command_, n) || is_input(dir_ / n, inputs_) ||
        !fs::is_regular_file(dir_ / n, ec)) {
      continue;
    }
    if (n == status) {
      std::ifstream in(dir_ / n, std::ios::binary);
      result = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
      if (result.is_discarded()) result = nullptr;
    }
    fs::rename(dir_ / n, io::partial_path(dir_ / n), ec);
  }
  if (claims_folder(command_)) io::remove_recorded_plots(dir_);  // view, export-aem: not theirs
  if (!status.empty()) {
    io::write_failure_status(dir_, status, kind_, scenario_, static_cast<int>(f.code), f.message,
                             result);
  }
  if (signalled) throw io::Interrupted(f.message);
  std::rethrow_exception(error);
}

void run_in_folder(OutputFolder& folder, const std::string& kind, const fs::path& scenario,
                   const std::function<void()>& body, bool claim_first) {
  if (claim_first) folder.claim();
  folder.set_subject(kind, scenario.string());
  try {
    body();
  } catch (...) {
    folder.fail(std::current_exception());
  }
}

}  // namespace attiguard::app
