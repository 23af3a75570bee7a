#pragma once
/// @file kinds.hpp
/// The scenario kinds `attiguard run` and `attiguard check` know, and how to run each.

#include <filesystem>
#include <span>
#include <string_view>

#include <nlohmann/json.hpp>

#include "attiguard/scenario/document.hpp"

namespace attiguard::scenario {

/// Options common to every run.
struct RunOptions {
  std::filesystem::path out_dir;  ///< created if missing; receives trajectory.csv, summary.json
  /// false: campaigns (attiguard campaign) only need the summary; kinds that can simulate in
  /// memory then write nothing (pet_erg), the others still write into out_dir (a scratch dir).
  bool write_files{true};
};

/// One scenario kind.
struct KindHandler {
  std::string_view name;         ///< value of the top-level `kind` key
  std::string_view description;  ///< one line for `attiguard --help`
  /// Parses and validates the document; throws InputError.
  void (*check)(const Document& doc);
  /// Runs it, writes DIR/trajectory.csv and DIR/summary.json (with wall_time_s), and returns
  /// the summary. Throws InputError / NumericalError / VerificationFailure.
  nlohmann::json (*run)(const Document& doc, const RunOptions& options);
};

/// Every registered kind.
[[nodiscard]] std::span<const KindHandler> kinds();

/// The handler of the document's kind; throws InputError naming the `kind` key and listing the
/// known kinds when it is unknown.
[[nodiscard]] const KindHandler& handler_for(const Document& doc);

}  // namespace attiguard::scenario
