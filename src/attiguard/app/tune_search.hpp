#pragma once
/// @file tune_search.hpp
/// Gain search of a pet_erg scenario (docs/pet-erg.md, section "Tuning"): log-uniform Latin
/// hypercube sampling of the tuned keys, then local refinement around the fastest admissible
/// point; every candidate is checked by the kind's parser (Γ_d admissibility) and run in memory
/// on the MPI ranks and their worker threads (tune_batch.hpp). Deterministic for a given seed
/// whatever the rank and thread counts.

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "attiguard/parallel/mpi_world.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/tune_table.hpp"

namespace attiguard::app {

/// One tuned key, searched log-uniformly on [min, max] (0 < min <= max): the entry of a
/// `[tune.ranges]` table or a `--range` (one definition, scenario/tune_table.hpp).
using TuneParameter = scenario::TuneRange;

/// What to search and how long.
struct TuneSettings {
  std::vector<TuneParameter> parameters;
  long budget{64};          ///< runs in all (half sampling, half refinement)
  std::uint64_t seed{1};
  int threads{1};                 ///< worker threads of each rank
  /// Points per refinement batch (docs/pet-erg.md, section 15); not tied to the worker count,
  /// so that the points do not depend on it.
  long batch{4};
  std::filesystem::path scratch;  ///< working directory of the runs (nothing is written)
  parallel::World world{};        ///< the ranks that share each batch ({0, 1}: this process)
  /// When set and true (the program's interruption flag, io/interruption.hpp), the workers take
  /// no further candidate and the search ends after the batch in hand, keeping the points
  /// evaluated so far (docs/pet-erg.md, section 15, "Interruption").
  const std::atomic<bool>* stop{nullptr};
};

/// One evaluated candidate.
struct TunePoint {
  long index{0};
  std::string phase;                 ///< "sample", "refine" (or "nominal": the scenario as given)
  std::vector<double> values;        ///< TuneSettings::parameters order
  /// "ok", "rejected" (the parser refused it), "failed", or "stopped" (not evaluated: the
  /// search was stopped first; never among TuneResult::points)
  std::string status;
  std::string outcome;               ///< summary outcome when ok
  std::string reason;                ///< why rejected/failed, or outcome_reason
  long violations{0};                ///< `*_satisfied` flags that are false
  std::optional<double> convergence_time;
  std::optional<double> ratio;       ///< convergence_time_over_bang_bang
  std::optional<double> bang_bang_time;  ///< eigenaxis_bang_bang_time of the slew
  /// ok, converged and no violation: a guaranteed manoeuvre.
  [[nodiscard]] bool admissible() const noexcept {
    return status == "ok" && outcome == "converged" && violations == 0 && convergence_time.has_value();
  }
};

/// The whole search.
struct TuneResult {
  std::vector<TunePoint> points;     ///< in evaluation order (index)
  std::optional<std::size_t> best;   ///< fastest admissible point, if any
  std::optional<double> eigenaxis_bang_bang_time;  ///< from the nominal run's summary
  TunePoint nominal;                 ///< the scenario as given (values: its keys, NaN if absent)
  /// The search ended before its budget because TuneSettings::stop was set (points: those
  /// evaluated before; docs/pet-erg.md, section 15, "Interruption").
  bool stopped{false};
};

/// The half-widths (factors) of the default search space around the values derived from the
/// craft (docs/pet-erg.md, section 15): each key is searched log-uniformly on [x/f, x f], i.e.
/// over a fixed range of its dimensionless group (c_p = k_p θ_ref/τ_eff, ζ, T_s ω_n).
struct TuneSpaceConstants {
  double stiffness{10.0};       ///< k_p: c_p in [0.8, 80]
  double damping{5.0};          ///< k_d: ζ in [0.1, 2.5]
  double sampling_period{10.0}; ///< T_s: T_s ω_n in [0.025, 2.5] (not below the control period)
};

/// The log-ranges of the planned mode's search space (docs/pet-erg.md, sections 15 and 16.2):
/// each value ×/÷ its factor around what the mode derives from the craft.
struct PlannedTuneSpaceConstants {
  double stiffness{10.0};  ///< k_R: ω_n ×/÷ √10
  double damping{3.0};     ///< k_Ω
  double headroom{3.0};    ///< the plan's torque headroom, within [0.01, 0.6]
  double margin{3.0};      ///< the plan's cone margin, at most 20°
};

/// Default search space, centred on the values governor::derive_governor_values derives from the
/// craft alone (whatever the file gives) and scaled by TuneSpaceConstants (docs/pet-erg.md,
/// sections 8 and 15); with governor = "planned", the tracking gains and the plan's headroom and
/// cone margin, centred on what the planned mode derives (docs/pet-erg.md, section 16.2) and
/// scaled by PlannedTuneSpaceConstants. Throws InputError when the scenario is not pet_erg.
[[nodiscard]] std::vector<TuneParameter> default_tune_parameters(const scenario::Document& nominal);

/// The keys whose value lies within `fraction` of its log-range from a bound (docs/pet-erg.md,
/// section 15): tune.json's `best_on_bound`, and a warning on stdout.
[[nodiscard]] std::vector<std::string> keys_on_bound(const std::vector<TuneParameter>& parameters,
                                                     const std::vector<double>& values,
                                                     double fraction = 0.02);

/// Parses "KEY=MIN:MAX" (docs/pet-erg.md, "Tuning"); throws InputError naming the option.
[[nodiscard]] TuneParameter parse_tune_range(const std::string& text);

/// The scenario with the parameters' keys set to `values`.
[[nodiscard]] scenario::Document tune_candidate(const scenario::Document& nominal,
                                                const std::vector<TuneParameter>& parameters,
                                                const std::vector<double>& values);

/// Evaluates one candidate (check, run in memory, classify). Never throws for the run itself.
[[nodiscard]] TunePoint evaluate_candidate(const scenario::Document& nominal,
                                           const std::vector<TuneParameter>& parameters,
                                           const std::vector<double>& values,
                                           const std::filesystem::path& scratch);

/// Runs the search (docs/pet-erg.md, "Tuning"). Collective over settings.world: every rank
/// calls it and gets the whole result. Throws InputError for a bad space or budget.
[[nodiscard]] TuneResult tune_search(const scenario::Document& nominal, const TuneSettings& settings);

/// DIR/tune.json: settings, best gains, convergence time and ratio, every point.
[[nodiscard]] nlohmann::json tune_json(const TuneSettings& settings, const TuneResult& result);

}  // namespace attiguard::app
