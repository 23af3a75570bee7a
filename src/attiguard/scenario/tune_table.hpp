#pragma once
/// @file tune_table.hpp
/// The optional `[tune]` table of a pet_erg scenario (docs/scenario-format.md, "[tune]";
/// docs/pet-erg.md, section 15): the settings of `attiguard tune` kept with the scenario, as an
/// alternative to its flags (a flag overrides its key). The kinds' parsers ignore the table.
///
///   [tune]
///   budget = 400                 # runs in all, >= 4
///   seed = 7                     # 0 to 2^63 - 1
///   batch = 8                    # points per refinement batch, >= 1 (default 4)
///   plot = false
///   [tune.ranges]                # replaces the default space
///   "control.kp" = [0.1, 10]     # KEY = [MIN, MAX], 0 < MIN <= MAX, searched log-uniformly

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "attiguard/scenario/document.hpp"

namespace attiguard::scenario {

/// One entry of `[tune.ranges]`: a number of the scenario searched on [min, max].
struct TuneRange {
  std::string key;  ///< key path, e.g. "control.kp"
  double min{0.0};
  double max{0.0};
};

/// The keys of `[tune]` that were given (absent keys are empty).
struct TuneTable {
  std::optional<long> budget;
  std::optional<std::uint64_t> seed;
  std::optional<long> batch;
  std::optional<bool> plot;
  std::vector<TuneRange> ranges;  ///< in key order; empty when `ranges` is absent
};

/// Reads `[tune]` of `doc` (all keys optional; nothing when the table is absent). Throws
/// InputError "FILE:LINE:COL: tune.KEY: …" for a budget below 4, a batch below 1, a seed out of range, a range
/// that is not [MIN, MAX] with 0 < MIN <= MAX, a range key that cannot be set in the scenario
/// (scenario/document_edit.hpp, set_number), an empty `ranges` table, or an unknown key.
[[nodiscard]] TuneTable read_tune_table(const Document& doc);

}  // namespace attiguard::scenario
