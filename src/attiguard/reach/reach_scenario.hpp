#pragma once
/// @file reach_scenario.hpp
/// The validated configuration of a `reach` analysis (ConReach, ConReach paper, Algorithm 1): the
/// closed loop, the initial set, the settings, the partition, soundness sampling and the safety
/// specification. Read by scenario::parse_reach (keys: docs/scenario-format.md, section "reach");
/// consumed by the reach driver app/reach_run.

#include <memory>
#include <string>

#include "attiguard/core/name_table.hpp"
#include "attiguard/reach/auto_split.hpp"
#include "attiguard/reach/closed_loop.hpp"
#include "attiguard/reach/conreach.hpp"
#include "attiguard/reach/safety.hpp"
#include "attiguard/reach/soundness.hpp"

namespace attiguard::reach {

/// Names of RateMode in scenario files and reach.json (docs/reach.md).
inline constexpr NameTable<RateMode, 2> kRateModeNames{
    {{{RateMode::line_search, "line_search"}, {RateMode::min_enclosure, "min_enclosure"}}}};

/// Names of MetricKind in scenario files and reach.json (docs/reach.md, "Coupled metrics").
inline constexpr NameTable<MetricKind, 2> kMetricNames{
    {{{MetricKind::product, "product"}, {MetricKind::coupled, "coupled"}}}};

/// Names of Rigour in scenario files and reach.json (docs/reach.md, "Rigour").
inline constexpr NameTable<Rigour, 2> kRigourNames{
    {{{Rigour::rigorous, "rigorous"}, {Rigour::floating, "float"}}}};

/// The default of `reach.sdp_solver` (docs/scenario-format.md; docs/reach.md, "Dense SDP solver").
inline constexpr SdpSolverKind kDefaultSdpSolver = SdpSolverKind::dense;

/// Names of SdpSolverKind in scenario files and reach.json (docs/reach.md, "Dense SDP solver").
inline constexpr NameTable<SdpSolverKind, 2> kSdpSolverNames{
    {{{SdpSolverKind::csdp, "csdp"}, {SdpSolverKind::dense, "dense"}}}};

/// Everything a `reach` run needs, validated.
struct ReachScenario {
  std::string name;
  std::shared_ptr<const ClosedLoop> loop;  ///< [system]
  std::string model;                       ///< [system] model
  InitialSet initial;                      ///< [initial]
  ConReachSettings settings;               ///< [reach]
  int attitude_cells{1};                   ///< [partition] attitude_cells (per axis)
  int omega_cells{1};                      ///< [partition] omega_cells (per axis)
  int threads{0};                          ///< [partition] threads (0: all cores)
  SplitSettings split;                     ///< [partition] split, max_cell_steps, max_seconds
  SoundnessSettings soundness;             ///< [soundness]
  SafetySpec safety;                       ///< [safety]
  int boundary_points{200};                ///< [output] boundary_points
};

}  // namespace attiguard::reach
