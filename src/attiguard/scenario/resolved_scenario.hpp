#pragma once
/// @file resolved_scenario.hpp
/// The resolved scenario (docs/conventions.md, "Outputs"): the scenario file with the defaults
/// its readers used filled in, written beside each output as scenario.resolved.toml so that a
/// result records exactly what it was computed from.

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "attiguard/scenario/document.hpp"

namespace attiguard::scenario {

/// The name of the resolved scenario in an output folder.
inline constexpr const char* kResolvedScenarioFile = "scenario.resolved.toml";

/// A default value a reader used for an absent key.
using DefaultValue = std::variant<double, std::int64_t, bool, std::string>;

/// One default a reader used: its key path, its value, and whether the value was derived from
/// other values of the scenario (TableReader::number_or with a DerivedDefault, e.g.
/// attitude_bias_bound = ‖attitude_bias‖ or a waypoint craft's gains from its mass) rather
/// than a constant of the schema.
struct RecordedDefault {
  std::string path;
  DefaultValue value;
  bool derived{false};
};

/// Which recorded defaults resolved_toml writes: every one (a scenario that is run as it is:
/// `run`, `reach`, a campaign's replayed run), or only the constants (a campaign scenario,
/// whose dispersed runs each derive the derived ones again from their own values).
enum class WrittenDefaults { every, constants_only };

/// While alive, collects on its thread every default the TableReader accessors `number_or`,
/// `integer_or`, `boolean_or` and `string_or` return for an absent key (key path and value),
/// except the keys the scenario's other settings leave unused (TableReader::used_only_if: the
/// reader would refuse them if written) and fallbacks outside the key's own rule (a "not set"
/// marker such as robust_reference_step = 0, which the reader would refuse if written).
/// A table left out that is read through TableReader::table_or_empty ([erg]) has its defaults
/// recorded like any other; defaults the kinds apply without such an accessor (an absent
/// [initial] attitude or omega_b, reach's [partition], [soundness], [output] left out, a
/// waypoint craft's derived [attitude_control] and [fine_position] left out) are not seen.
/// Recorders do not nest.
class DefaultsRecorder {
 public:
  DefaultsRecorder() noexcept;
  ~DefaultsRecorder();
  DefaultsRecorder(const DefaultsRecorder&) = delete;
  DefaultsRecorder& operator=(const DefaultsRecorder&) = delete;

  /// The defaults recorded so far, in reading order, without the unused keys.
  [[nodiscard]] const std::vector<RecordedDefault>& defaults() const noexcept { return defaults_; }

  /// Called by the readers (no effect without a recorder on this thread).
  static void record(std::string path, DefaultValue value, bool derived = false);
  /// Called by a reader that derives the default of `path` after a TableReader accessor recorded
  /// a constant for it (the PET-ERG's values of docs/pet-erg.md, section 8): the earlier entry is
  /// replaced by `value`, marked derived (no effect without a recorder).
  static void replace_derived(std::string path, DefaultValue value);
  /// Called by TableReader::used_only_if for a key the other settings leave unused: its
  /// default, recorded before or after, is not one (no effect without a recorder).
  static void record_unused(std::string path);

 private:
  std::vector<RecordedDefault> defaults_;
  std::vector<std::string> unused_;
};

/// The TOML text of `doc` with `defaults` (those `which` selects) inserted at their key paths,
/// headed by a comment naming `source` (default: the document's file) and the attiguard version.
[[nodiscard]] std::string resolved_toml(const Document& doc,
                                        const std::vector<RecordedDefault>& defaults,
                                        WrittenDefaults which = WrittenDefaults::every,
                                        std::string_view source = {});

/// Reads `doc` with `check` (a kind's validation) under a recorder and returns resolved_toml of
/// it with every default: what `run` and `reach` write, and a campaign's replay for the
/// dispersed document of its run (`source` then names the run). Throws what `check` throws.
[[nodiscard]] std::string resolve_scenario(const Document& doc, void (*check)(const Document&),
                                           std::string_view source = {});

/// The resolved scenario of a campaign file `doc` (docs/conventions.md, "Outputs"): its nominal scenario
/// (scenario::nominal_document) read with `check` and its [dispersions] and [campaign] tables
/// read by scenario::read_dispersions, under one recorder; written with the constant defaults
/// only (WrittenDefaults::constants_only), so that `attiguard campaign` of it draws and runs
/// the same runs. Throws what `check` and read_dispersions throw.
[[nodiscard]] std::string resolve_campaign(const Document& doc, void (*check)(const Document&));

}  // namespace attiguard::scenario
