#pragma once
/// @file kinds.hpp
/// The scenario kinds `attiguard run` and `attiguard check` know, and how to run each
/// (docs/architecture.md, "Data flow of attiguard run"): parse the document into the kind's
/// validated configuration (scenario/), simulate it with the rows going into a sink (sim/),
/// turn the typed result into the summary and write DIR/trajectory.csv and DIR/summary.json.

#include <filesystem>
#include <span>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "attiguard/io/row_sink.hpp"
#include "attiguard/scenario/document.hpp"

namespace attiguard::app {

/// Options common to every run.
struct RunOptions {
  std::filesystem::path out_dir;  ///< created if missing; receives trajectory.csv, summary.json
  /// false: campaigns (attiguard campaign) only need the summary; nothing is written.
  bool write_files{true};
  /// Receives the trajectory rows as well (the Python bindings' numpy arrays), when set.
  io::RowSink* rows{nullptr};
};

/// One scenario kind.
struct KindHandler {
  std::string_view name;         ///< value of the top-level `kind` key
  std::string_view description;  ///< one line for `attiguard --help`
  /// Parses and validates the document; throws InputError.
  void (*check)(const scenario::Document& doc);
  /// Runs it, writes DIR/trajectory.csv and DIR/summary.json (with wall_time_s) when
  /// options.write_files, and returns the summary. Throws InputError / NumericalError /
  /// VerificationFailure.
  nlohmann::json (*run)(const scenario::Document& doc, const RunOptions& options);
  /// The one-line outcome of the summary `run` returned (app/outcome_line.hpp; for kind reach,
  /// of reach.json).
  std::string (*outcome_line)(const nlohmann::json& summary);
  /// The key most likely responsible for a numerical failure of a run of `doc`, located, with a
  /// hint (app/numerical_hints.hpp, docs/errors.md "Numerical failures"), or "" when none stands
  /// out; null for a kind without hints.
  std::string (*numerical_hint)(const scenario::Document& doc){nullptr};
  /// What `attiguard check` prints after "OK" for a valid `doc` (kind waypoint: the mission-time
  /// and Δv prediction, docs/waypoint.md "Prediction"), "" or null for nothing.
  std::string (*check_report)(const scenario::Document& doc){nullptr};
};

/// Every registered kind.
[[nodiscard]] std::span<const KindHandler> kinds();

/// The handler of the document's kind; throws InputError naming the `kind` key and listing the
/// known kinds when it is unknown.
[[nodiscard]] const KindHandler& handler_for(const scenario::Document& doc);

}  // namespace attiguard::app
