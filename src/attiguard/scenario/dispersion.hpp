#pragma once
/// @file dispersion.hpp
/// The `[dispersions]` table of a campaign scenario (docs/campaigns.md): what to disperse, how,
/// and its application to a copy of the scenario's TOML table.
///
///   [dispersions]
///   "control.kp"           = { distribution = "uniform", min = 4.0, max = 6.0 }
///   "initial.omega_b"      = { type = "vector", distribution = "truncated_normal",
///                              sigma = 0.05, delta = 0.1 }
///   "body.inertia"         = { type = "inertia", moments_rel_sigma = 0.1, axes_max_angle_deg = 5 }
///   "initial.attitude"     = { type = "attitude", mode = "ball", max_angle_deg = 20 }
///   "cones[0].direction_i" = { type = "direction", half_angle_deg = 5 }
///   "waypoints"            = { type = "waypoints", count_min = 1, count_max = 4,
///                              leg_min = 20.0, leg_max = 5e4, turn_max_deg = 90 }

#include <string>
#include <vector>

#include "attiguard/campaign/retain_plan.hpp"
#include "attiguard/campaign/seed.hpp"
#include "attiguard/scenario/document.hpp"

namespace attiguard::scenario {

/// What a dispersion changes.
enum class DispersionType { number, vector, inertia, attitude, direction, waypoints };
/// Distribution of a scalar (number, and each component of a vector).
enum class Distribution { uniform, normal, truncated_normal };
/// Attitude dispersion: uniform on SO(3), or uniform within a geodesic ball around the nominal.
enum class AttitudeMode { uniform, ball };

/// One entry of `[dispersions]`.
struct Dispersion {
  std::string key;  ///< key path in the scenario, e.g. "cones[0].direction_i"
  DispersionType type{DispersionType::number};
  Distribution distribution{Distribution::uniform};
  // number / vector: absolute bounds (uniform, truncated_normal) or ± delta around the nominal
  bool has_bounds{false};
  double min{0.0}, max{0.0};
  double delta{0.0};       ///< half-width around the nominal (when no min/max)
  bool has_mean{false};
  double mean{0.0};        ///< normal mean (default: the nominal value)
  double sigma{0.0};       ///< normal standard deviation
  // inertia
  double moments_rel_sigma{0.0};   ///< relative σ of each principal moment (truncated at 3σ)
  double axes_max_angle{0.0};      ///< rad: principal axes rotated within this geodesic ball
  // attitude
  AttitudeMode attitude_mode{AttitudeMode::ball};
  double max_angle{0.0};           ///< rad (attitude ball)
  // direction
  double half_angle{0.0};          ///< rad: uniform on the spherical cap around the nominal
  // waypoints: a new list of count_min … count_max legs from [initial] position
  long count_min{1};
  long count_max{1};
  double leg_min{0.0};             ///< [m], legs log-uniform in [leg_min, leg_max]
  double leg_max{0.0};
  double turn_max{0.0};            ///< rad: each leg's direction within this cap of the previous
};

/// Most waypoints a `waypoints` dispersion draws (docs/campaigns.md, "[dispersions]").
inline constexpr long kMaxDispersedWaypoints = 64;
/// Longest leg a `waypoints` dispersion draws [m]: 64 legs of it stay inside the waypoint
/// kinds' bound of one light-year from the origin.
inline constexpr double kMaxDispersedLeg = 1e14;

/// The parsed dispersions of a campaign and the scenario they apply to.
struct DispersionPlan {
  std::vector<Dispersion> items;   ///< in the order of the file (the parser keeps keys sorted)
  long max_attempts{1};            ///< [campaign] max_attempts: draws until admissible
  campaign::RetainPlan retain;     ///< [campaign] retain, retain_interval (retain_keys.hpp)
};

/// Reads `[dispersions]` (required, non-empty) and `[campaign]` (optional) of `doc`, checks every
/// key path exists in the scenario with a value of the right shape; throws InputError located
/// at the offending key.
[[nodiscard]] DispersionPlan read_dispersions(const scenario::Document& doc);

/// How far a `normal` dispersion of a number is probed: mean ± kNormalProbeSigmas σ (a draw
/// beyond it has probability 2·10⁻⁹).
inline constexpr double kNormalProbeSigmas = 6.0;

/// Refuses a `normal` dispersion of a number whose mean ± kNormalProbeSigmas σ the scenario's
/// own validation `check` (the kind's: shared, not a copy) refuses at that very key, i.e. a
/// normal crossing a physical bound such as k_p > 0 (docs/campaigns.md), with the numbers and
/// the kind's message; located at the entry's `sigma` in `doc` (the campaign file). Values
/// refused at another key (admissibility of the initial state, …) stay rejected draws.
void check_dispersion_bounds(const DispersionPlan& plan, const scenario::Document& doc,
                             void (*check)(const scenario::Document&));

/// The scenario without its `[dispersions]` and `[campaign]` tables (what the kind validates).
[[nodiscard]] scenario::Document nominal_document(const scenario::Document& doc);

/// Names of the columns of the dispersed values, in order (e.g. "initial.omega_b[0]").
[[nodiscard]] std::vector<std::string> dispersion_columns(const DispersionPlan& plan);

/// Draws every dispersion from `rng` and writes the dispersed values into `out` (a copy of the
/// nominal document); appends the drawn values (dispersion_columns order) to `values`.
void apply_dispersions(const DispersionPlan& plan, const scenario::Document& nominal, campaign::Rng& rng,
                       Document& out, std::vector<double>& values);

}  // namespace attiguard::scenario
