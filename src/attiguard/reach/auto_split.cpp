#include "attiguard/reach/auto_split.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <string_view>

#include "attiguard/core/errors.hpp"
#include "attiguard/reach/metrics.hpp"
#include "attiguard/reach/partition.hpp"
#include "attiguard/reach/simulate.hpp"

namespace attiguard::reach {

bool nominal_violates(const ClosedLoop& loop, const InitialSet& cell, double horizon, const SafetySpec& spec,
                      std::string& where) {
  if (!spec.requested()) return false;
  constexpr int kPoints = 2000;
  std::vector<double> times;
  for (int k = 0; k <= kPoints; ++k) times.push_back(horizon * k / kPoints);
  const double h = std::min(horizon / kPoints, 0.02 / std::max(loop_rate_scale(loop, cell), 1e-12));
  bool found = false;
  try {
    simulate(loop, cell.R0, cell.omega0, times, h, [&](std::size_t k, const Mat3& R, const Vec3& w) {
    if (found) return;
    const std::string why = violated_by_state(spec, R, w);
    if (why.empty()) return;
    std::ostringstream os;
    os << why << " at t = " << times[k] << " s";
    where = os.str();
    found = true;
  });
  } catch (const NumericalError& e) {
    throw NumericalError(std::string("reach: the trajectory from a cell's centre: ") + e.what());
  }
  return found;
}

std::vector<InitialSet> split_cell(const InitialSet& cell, bool attitude) {
  return attitude ? partition_initial_set(cell, 3, 1) : partition_initial_set(cell, 1, 3);
}

bool split_attitude_first(const InitialSet& cell, const ReachResult& res) {
  if (cell.omega_radius <= 0.0) return true;
  if (cell.attitude_radius <= 0.0) return false;
  const StateMetric M = res.steps.empty() ? StateMetric{Mat3::Identity(), Mat3::Zero(), cell.P0}
                                          : StateMetric{res.Q0, res.S0, res.P0};
  return metric_cover_radius(M, cell.attitude_radius, 0.0) >= metric_cover_radius(M, 0.0, cell.omega_radius);
}

namespace {

/// Work of one cell's analysis: its steps, the redone ones included (at least 1).
long cell_work(const ReachResult& res) {
  return std::max<long>(1, static_cast<long>(res.steps.size()) + res.retries);
}

/// True on every rank when any rank says stop (a collective: every rank calls it).
bool any_rank(bool mine, const parallel::World& world) {
  if (world.size == 1) return mine;
  for (const std::string& b : parallel::allgather_bytes(mine ? "1" : "0", world)) {
    if (b == "1") return true;
  }
  return false;
}

/// Empty when the budget pays for `cells` more cells of about `mean_work` steps each, else which
/// budget they would exceed, with the figures.
std::string over_budget(const SplitSettings& split, const SplitReport& rep, std::size_t cells, double mean_work,
                        double seconds_per_step, double elapsed) {
  const double next_work = mean_work * static_cast<double>(cells);
  const double next_seconds = next_work * seconds_per_step;
  std::ostringstream why;
  if (static_cast<double>(rep.cell_steps) + next_work > static_cast<double>(split.max_cell_steps)) {
    why << "max_cell_steps = " << split.max_cell_steps << ": " << rep.cell_steps << " cell-steps spent, "
        << cells << " more cells need about " << static_cast<long>(next_work);
  } else if (elapsed + next_seconds > split.max_seconds) {
    why << "max_seconds = " << split.max_seconds << ": " << elapsed << " s spent, " << cells
        << " more cells need about " << next_seconds << " s";
  }
  return why.str();
}

/// The cells of one round of the splitting, their depths and their parents' first unproved
/// times (−∞ for the user's cells).
struct Round {
  std::vector<InitialSet> cells;
  std::vector<int> depth;
  std::vector<double> parent_fail;
  std::vector<long> family;  ///< cells with the same parent share it (the user's cells: their own)
  /// Per family of a split round: the parent, its result and depth (the leaf it stays when the
  /// time budget runs out in its children's round).
  std::vector<InitialSet> parent_cell;
  std::vector<ReachResult> parent_result;
  std::vector<int> parent_depth;
};

/// The reason step_check gives when the time budget runs out (stopping_settings).
constexpr std::string_view kTimeBudgetReason = "the time budget ran out";

/// Whether the analysis was stopped by the time budget rather than by its own failure.
bool stopped_by_time(const ReachResult& res) {
  return !res.complete && res.stop_reason.starts_with(kTimeBudgetReason);
}

/// Per family of the round: whether any of its cells is proved or proves further than the parent
/// (first unproved time later by 10⁻³ T). A family without progress stalled.
std::vector<bool> family_progress(const Round& round, const std::vector<SafetyVerdict>& verdicts, double horizon) {
  long families = 0;
  for (const long f : round.family) families = std::max(families, f + 1);
  std::vector<bool> progress(static_cast<std::size_t>(families), false);
  for (std::size_t c = 0; c < round.cells.size(); ++c) {
    const SafetyVerdict& v = verdicts[c];
    if (v.proved || v.first_failure_time > round.parent_fail[c] + 1e-3 * horizon) {
      progress[static_cast<std::size_t>(round.family[c])] = true;
    }
  }
  return progress;
}

/// The settings the cells run with. With splitting, a cell's analysis ends at its first segment
/// that cannot prove the specification (the cell is then split or left unproved whatever
/// follows), and at the first step that ends after the time budget (`deadline`).
ConReachSettings stopping_settings(const ConReachSettings& settings, const SafetySpec& spec,
                                   const SplitSettings& split, std::chrono::steady_clock::time_point deadline) {
  ConReachSettings run_settings = settings;
  if (!split.enabled) return run_settings;
  const double budget = split.max_seconds;
  run_settings.step_check = [&spec, deadline, budget](const ReachStep& st, double& t) {
    for (const TubeSegment& seg : st.state_tube) {
      const std::string why = spec.requested() ? violated_by_segment(spec, seg) : std::string();
      if (why.empty()) continue;
      t = seg.t0;
      std::ostringstream os;
      os << why << " cannot be proved on [" << seg.t0 << ", " << seg.t1 << "] s";
      return os.str();
    }
    if (std::chrono::steady_clock::now() > deadline) {
      t = st.t1;
      std::ostringstream os;
      os << kTimeBudgetReason << " (max_seconds = " << budget << ")";
      return os.str();
    }
    return std::string();
  };
  return run_settings;
}

/// Cell c of the round into the leaves.
void add_leaf(SplitOutcome& out, const Round& round, std::size_t c, ReachResult&& res) {
  out.cells.push_back(round.cells[c]);
  out.results.push_back(std::move(res));
  out.depth.push_back(round.depth[c]);
}

/// The round's cells that are proved, hopeless (their nominal violates), stalled (no cell of their
/// family proved or proving further than the parent, family_progress) or at the deepest split
/// become leaves; returns
/// the others, to be split, and each cell's first unproved time in `fail_time`.
std::vector<std::size_t> settle_round(const ClosedLoop& loop, double horizon, const SafetySpec& spec,
                                      const SplitSettings& split, const Round& round,
                                      std::vector<ReachResult>& results, std::vector<double>& fail_time,
                                      SplitOutcome& out) {
  SplitReport& rep = out.report;
  std::vector<std::size_t> to_split;
  fail_time.assign(round.cells.size(), -1.0);
  // A family of children cut by the time budget gives way to its parent: the children's stop
  // times say only when the budget ran out, the parent's first unproved time is its own.
  std::vector<bool> timed_out(round.parent_cell.size(), false);
  for (std::size_t c = 0; c < round.cells.size(); ++c) {
    if (!round.parent_cell.empty() && stopped_by_time(results[c])) {
      timed_out[static_cast<std::size_t>(round.family[c])] = true;
    }
  }
  for (std::size_t f = 0; f < timed_out.size(); ++f) {
    if (!timed_out[f]) continue;
    out.cells.push_back(round.parent_cell[f]);
    out.results.push_back(round.parent_result[f]);
    out.depth.push_back(round.parent_depth[f]);
    ++rep.leaves_unproved;
    rep.budget_spent = true;
    std::ostringstream os;
    os << "max_seconds = " << split.max_seconds << ": the time budget ran out during a round";
    rep.budget_reason = os.str();
  }
  std::vector<SafetyVerdict> verdicts;
  for (const ReachResult& res : results) verdicts.push_back(verify_safety(spec, {res}));
  const std::vector<bool> progress = family_progress(round, verdicts, horizon);
  for (std::size_t c = 0; c < round.cells.size(); ++c) {
    if (!round.parent_cell.empty() && timed_out[static_cast<std::size_t>(round.family[c])]) continue;
    const SafetyVerdict& v = verdicts[c];
    fail_time[c] = v.first_failure_time;
    std::string where;
    const bool hopeless = !v.proved && split.enabled && nominal_violates(loop, round.cells[c], horizon, spec, where);
    const bool stalled = !v.proved && split.enabled && !hopeless && !progress[static_cast<std::size_t>(round.family[c])];
    const bool deepest = round.depth[c] >= split.max_depth;
    if (!v.proved && split.enabled && !hopeless && !stalled && !deepest) {
      to_split.push_back(c);
      continue;
    }
    rep.nominal_violations += hopeless ? 1 : 0;
    if (hopeless && rep.first_violation.empty()) rep.first_violation = where;
    rep.stalled += stalled ? 1 : 0;
    if (!v.proved) ++rep.leaves_unproved;
    if (!v.proved && deepest && !hopeless && !stalled && split.enabled && !rep.budget_spent) {
      rep.budget_spent = true;
      rep.budget_reason = "a cell reached the deepest split (max_depth = " + std::to_string(split.max_depth) + ")";
    }
    add_leaf(out, round, c, std::move(results[c]));
  }
  return to_split;
}

/// The next round: the 27 children of every cell to split.
Round children_of(const Round& round, const std::vector<std::size_t>& to_split,
                  const std::vector<ReachResult>& results, const std::vector<double>& fail_time) {
  Round next;
  long family = 0;
  for (const std::size_t c : to_split) {
    for (const InitialSet& child : split_cell(round.cells[c], split_attitude_first(round.cells[c], results[c]))) {
      next.cells.push_back(child);
      next.depth.push_back(round.depth[c] + 1);
      next.parent_fail.push_back(fail_time[c]);
      next.family.push_back(family);
    }
    next.parent_cell.push_back(round.cells[c]);
    next.parent_result.push_back(results[c]);
    next.parent_depth.push_back(round.depth[c]);
    ++family;
  }
  return next;
}

}  // namespace

SplitOutcome run_with_splitting(const ClosedLoop& loop, const std::vector<InitialSet>& cells,
                                const ConReachSettings& settings, const SafetySpec& spec,
                                const SplitSettings& split, int threads, const parallel::World& world) {
  const auto wall0 = std::chrono::steady_clock::now();
  auto elapsed = [&wall0]() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  };
  SplitOutcome out;
  SplitReport& rep = out.report;
  const auto deadline = wall0 + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                    std::chrono::duration<double>(std::min(split.max_seconds, 1e9)));
  const ConReachSettings run_settings = stopping_settings(settings, spec, split, deadline);
  Round round{cells, std::vector<int>(cells.size(), 0),
              std::vector<double>(cells.size(), -std::numeric_limits<double>::infinity()), {}, {}, {}, {}};
  for (std::size_t c = 0; c < cells.size(); ++c) round.family.push_back(static_cast<long>(c));
  while (!round.cells.empty()) {
    const double round_start = elapsed();
    std::vector<ReachResult> results = run_partitioned(loop, round.cells, run_settings, threads, world);
    ++rep.rounds;
    rep.cells_analysed += static_cast<long>(round.cells.size());
    long round_work = 0;
    for (const ReachResult& r : results) round_work += cell_work(r);
    rep.cell_steps += round_work;
    const double seconds_per_step = (elapsed() - round_start) / static_cast<double>(round_work);

    std::vector<double> fail_time;
    const std::vector<std::size_t> to_split =
        settle_round(loop, settings.horizon, spec, split, round, results, fail_time, out);
    if (to_split.empty()) break;
    // The next round's children, each costing about this round's mean work, if the budget allows.
    Round next = children_of(round, to_split, results, fail_time);
    const double mean_work = static_cast<double>(round_work) / static_cast<double>(round.cells.size());
    const std::string why = over_budget(split, rep, next.cells.size(), mean_work, seconds_per_step, elapsed());
    if (any_rank(!why.empty(), world)) {
      rep.budget_spent = true;
      rep.budget_reason = why.empty() ? "the time budget on another rank" : why;
      for (const std::size_t c : to_split) add_leaf(out, round, c, std::move(results[c]));
      rep.leaves_unproved += static_cast<long>(to_split.size());
      break;
    }
    rep.cells_split += static_cast<long>(to_split.size());
    round = std::move(next);
  }
  for (const int d : out.depth) rep.max_depth = std::max(rep.max_depth, d);
  rep.seconds = elapsed();
  return out;
}

}  // namespace attiguard::reach
