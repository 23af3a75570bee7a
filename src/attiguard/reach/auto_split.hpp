#pragma once
/// @file auto_split.hpp
/// Automatic splitting of the initial set (docs/reach.md, "Automatic splitting"), the ConReach
/// paper's partitioning (Sec. 4.1) driven by the verdict: every cell whose analysis stops early
/// or whose tube cannot prove the safety specification is split — its attitude ball or its ω
/// ball, whichever contributes more to its first metric ball, into the 27 cells of
/// partition_initial_set with 3 per axis (radius ×1/√3) — and the children are analysed, round
/// after round, until every cell is proved or the work budget is spent. A cell whose own
/// nominal trajectory violates the specification is not split: no partition can prove it; nor are
/// the children of a cell when none of them is proved or proves further than their parent (first
/// unproved time later by 10⁻³ T): the splitting stalled there.

#include <string>
#include <vector>

#include "attiguard/parallel/mpi_world.hpp"
#include "attiguard/reach/conreach.hpp"
#include "attiguard/reach/safety.hpp"

namespace attiguard::reach {

/// The work budget of the splitting ([partition] split, max_cell_steps, max_seconds).
struct SplitSettings {
  bool enabled{true};
  long max_cell_steps{10000};  ///< ConReach steps summed over every cell analysed
  double max_seconds{60.0};    ///< wall time of the analysis [s]
  int max_depth{4};            ///< most successive splits of one cell
};

/// What the splitting did.
struct SplitReport {
  int rounds{0};
  long cells_analysed{0};
  long cells_split{0};
  int max_depth{0};            ///< deepest leaf
  long cell_steps{0};
  double seconds{0.0};
  bool budget_spent{false};    ///< a split was needed but the budget could not pay for it
  std::string budget_reason;   ///< which budget, with the figures
  long leaves_unproved{0};
  long nominal_violations{0};  ///< leaves not split because their nominal violates the spec
  std::string first_violation;  ///< the first of them: constraint and time on its nominal
  long stalled{0};             ///< leaves not split because their family proved no further than its parent
};

/// The leaves of the final partition: they cover the initial set; results[i] is cells[i]'s.
struct SplitOutcome {
  std::vector<InitialSet> cells;
  std::vector<ReachResult> results;
  std::vector<int> depth;  ///< splits from the user's cell
  SplitReport report;
};

/// Whether the trajectory from the cell's centre violates `spec` over [0, horizon] (a cone or an
/// ω bound at one of 2001 equally spaced instants, RKMK4 at ≤ 0.02/λ); `where` says which, and
/// when. Such a cell cannot be proved by any partition (evidence from a computed trajectory, not a
/// proof of the violation).
[[nodiscard]] bool nominal_violates(const ClosedLoop& loop, const InitialSet& cell, double horizon,
                                    const SafetySpec& spec, std::string& where);

/// The 27 cells that split `cell` along its attitude ball (attitude = true) or its ω ball.
[[nodiscard]] std::vector<InitialSet> split_cell(const InitialSet& cell, bool attitude);

/// Whether to split the attitude ball (else the ω ball) of a cell analysed as `res`: the part
/// with the larger cover radius in the cell's first metric (metric_cover_radius of (a, 0) and
/// (0, b); diag(I, P0) when no step was carried).
[[nodiscard]] bool split_attitude_first(const InitialSet& cell, const ReachResult& res);

/// ConReach on `cells` (run_partitioned: threads and MPI ranks), then the splitting rounds.
/// Deterministic across ranks: the time budget is decided on every rank from the slowest one.
[[nodiscard]] SplitOutcome run_with_splitting(const ClosedLoop& loop, const std::vector<InitialSet>& cells,
                                              const ConReachSettings& settings, const SafetySpec& spec,
                                              const SplitSettings& split, int threads,
                                              const parallel::World& world = {});

}  // namespace attiguard::reach
