#pragma once
/// @file reach_run.hpp
/// The reach driver (docs/architecture.md): runs a `reach` configuration end to end and writes its outputs into a directory:
///   reach.json     summary (keys: docs/reach.md, "Outputs")
///   trajectory.csv nominal trajectory (first cell) at every sub-step time
///   steps.csv      per cell and step: t, c, r, Q, P, U_i ω box, attitude enclosure radius
///   tube.csv       state-tube segments (attitude ball radius, ω box) used by the safety check
///   boundary.csv   boundary points of the attitude balls in one exp chart (Sec. 5, Fig. 1b)
///   samples.csv    a few sampled trajectories (chart coordinates and ω) for plots

#include <filesystem>

#include <nlohmann/json.hpp>

#include "attiguard/parallel/mpi_world.hpp"
#include "attiguard/reach/reach_scenario.hpp"

namespace attiguard::app {

/// Runs the scenario and writes the outputs. Returns the summary (also in reach.json).
/// Throws NumericalError (solver/NaN/chart/soundness failure) or VerificationFailure (safety
/// requested and not proved) — in both cases after writing whatever was computed.
/// Under MPI the partition cells are split over the ranks of `world`; every rank gets the
/// verdict (and throws the same VerificationFailure), only rank 0 runs the soundness sampling
/// and writes files.
nlohmann::json run_reach(const reach::ReachScenario& sc, const std::filesystem::path& out_dir,
                         const parallel::World& world = {});

}  // namespace attiguard::app
