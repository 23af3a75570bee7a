#pragma once
/// @file partition.hpp
/// Partitioning of a larger initial set [ConReach Sec. 4.1]: a
/// deterministic cover of the attitude ball B(R0, a) by bi-invariant balls times a cover of the
/// ω ball B(ω0, b) by Euclidean balls; every cell is analysed independently, cells in parallel.
///
/// Attitude cover: a cubic grid of n³ points η_j (spacing h = 2a/n) in the exp chart around R0,
/// keeping those with ‖η_j‖ ≤ a + h√3/2; every R = R0 exp(η̂), ‖η‖ ≤ a, is within h√3/2 of a
/// grid point in the chart, and d(R0 exp(η̂), R0 exp(η̂_j)) ≤ ‖η − η_j‖ because the right
/// Jacobian of exp has singular values 2 sin(θ/2)/θ ≤ 1 and 1. So the balls B(R0 exp(η̂_j), h√3/2)
/// cover B(R0, a). The ω cover is the same grid in R³. n = 1 keeps the ball itself.

#include <vector>

#include "attiguard/parallel/mpi_world.hpp"
#include "attiguard/reach/conreach.hpp"

namespace attiguard::reach {

/// The cells covering `whole` (attitude grid n_att per axis, ω grid n_omega per axis).
[[nodiscard]] std::vector<InitialSet> partition_initial_set(const InitialSet& whole, int n_att,
                                                            int n_omega);

/// ConReach on every cell (ConReach paper, Sec. 4.1: cells are independent).
/// The cells are dealt round robin over the MPI ranks of `world` (parallel/mpi_world.hpp) and,
/// inside a rank, run `threads` at a time (0: hardware concurrency; SDP calls are serialised in
/// the solver wrapper); every rank returns all cells, bit for bit what one process computes.
/// Every cell runs even when one fails; then the error of the lowest failing cell is thrown
/// (same type and message on every rank and for every split).
[[nodiscard]] std::vector<ReachResult> run_partitioned(const ClosedLoop& loop,
                                                       const std::vector<InitialSet>& cells,
                                                       const ConReachSettings& settings, int threads,
                                                       const parallel::World& world = {});

}  // namespace attiguard::reach
