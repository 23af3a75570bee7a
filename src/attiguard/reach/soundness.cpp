#include "attiguard/reach/soundness.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <random>

#include "attiguard/core/errors.hpp"
#include "attiguard/reach/ball_membership.hpp"
#include "attiguard/reach/metrics.hpp"
#include "attiguard/reach/simulate.hpp"
#include "attiguard/parallel/parallel_for.hpp"

namespace attiguard::reach {

namespace {
/// Relative tolerance of the ball test: boundary samples of the initial set lie exactly on the
/// sphere of the initial ball, where rounding gives ratios of 1 ± 1e-16.
constexpr double kRoundoff = 1e-12;

/// How far (R, ω) lies outside the attitude ball and the ω box (0 inside, up to rounding). The
/// ball's test (ball_membership.hpp) skips the distance only where it proves it ≤ 0, which the
/// final max with 0 would erase: the value is the one of the exact distance.
double excess(const AttitudeBallTest& att, const Box3& box, const Mat3& R, const Vec3& w) {
  double e = att.excess_or_zero(R);
  for (int k = 0; k < 3; ++k) {
    const double tol = kRoundoff * (1.0 + std::abs(w(k)));
    e = std::max({e, box.lo(k) - tol - w(k), w(k) - box.hi(k) - tol});
  }
  return std::max(e, 0.0);
}

/// The membership test of an attitude ball at the check's tolerance radius·(1 + 10⁻¹²).
AttitudeBallTest ball_test(const AttitudeBall& att) {
  return {att.center, att.radius * (1.0 + kRoundoff)};
}

Vec3 sample_ball(std::mt19937_64& g, double radius, bool on_boundary) {
  std::normal_distribution<double> n(0.0, 1.0);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Vec3 v(n(g), n(g), n(g));
  while (v.norm() < 1e-12) v = Vec3(n(g), n(g), n(g));
  const double s = on_boundary ? 1.0 : std::cbrt(u(g));
  return v.normalized() * radius * s;
}

/// The cell whose initial set contains (R, ω); NumericalError when none does.
std::size_t containing_cell(const std::vector<InitialSet>& cells, const Mat3& R, const Vec3& w) {
  for (std::size_t c = 0; c < cells.size(); ++c) {
    if (lie::distance(cells[c].R0, R) <= cells[c].attitude_radius * (1 + 1e-12) + 1e-15 &&
        (w - cells[c].omega0).norm() <= cells[c].omega_radius * (1 + 1e-12) + 1e-15) {
      return c;
    }
  }
  throw NumericalError("soundness check: sample outside every cell");
}

/// What one sampled trajectory showed.
struct SampleOutcome {
  double worst{0.0};            ///< largest ball ratio at the t_i
  double violation{-1.0};       ///< first t_i outside the ball (−1: none)
  double worst_excess{0.0};     ///< largest excess over a tube segment or U_i
  double tube_violation{-1.0};  ///< first sub-step time outside them (−1: none)
  SampleTrajectory traj;        ///< filled when the sample is kept
};

/// Where the nominal points of a result sit: global segment g (from point g to g + 1) is
/// segment `segment[g].second` of step `segment[g].first`, and point k carries ball `ball[k]`
/// (0: the initial ball; −1: a sub-step boundary inside a step). Steps may have any number of
/// sub-steps (adaptive steps, bisected sub-steps).
struct PointIndex {
  std::vector<double> times;
  std::vector<std::pair<std::size_t, std::size_t>> segment;
  std::vector<long> ball;
  std::vector<AttitudeBallTest> segment_test;  ///< per global segment: its attitude ball
  std::vector<AttitudeBallTest> step_test;     ///< per step: the attitude ball of U_i
};

PointIndex index_points(const ReachResult& res) {
  PointIndex ix;
  for (const NominalPoint& p : res.nominal) ix.times.push_back(p.t);
  ix.ball.assign(ix.times.size(), -1);
  ix.ball[0] = 0;
  for (std::size_t i = 0; i < res.steps.size(); ++i) {
    const std::size_t n = res.steps[i].state_tube.size();
    for (std::size_t j = 0; j < n; ++j) {
      ix.segment.emplace_back(i, j);
      ix.segment_test.push_back(ball_test(res.steps[i].state_tube[j].attitude));
    }
    ix.step_test.push_back(ball_test(res.steps[i].attitude_box));
    if (ix.segment.size() < ix.ball.size()) ix.ball[ix.segment.size()] = static_cast<long>(i + 1);
  }
  if (ix.segment.size() + 1 != ix.times.size()) {
    throw NumericalError("soundness check: the nominal points and the tube segments do not match");
  }
  return ix;
}

/// The sample at nominal point k against tube segments g = k − 1 (ending at t_k) and g = k
/// (starting there), and their U_i (computed once when both segments are of the same step).
void check_tube_at(const ReachResult& res, const PointIndex& ix, std::size_t k, double t, const Mat3& Rk,
                   const Vec3& wk, SampleOutcome& out) {
  std::size_t u_step = ix.step_test.size();
  double u_excess = 0.0;
  for (const std::size_t g : {k - 1, k}) {
    if (g >= ix.segment.size()) continue;  // k − 1 wraps for k = 0
    const std::size_t i = ix.segment[g].first;
    const ReachStep& st = res.steps[i];
    const TubeSegment& seg = st.state_tube[ix.segment[g].second];
    if (i != u_step) {
      u_excess = excess(ix.step_test[i], st.omega_box, Rk, wk);
      u_step = i;
    }
    const double ex = std::max({excess(ix.segment_test[g], seg.omega, Rk, wk), u_excess,
                                wk.norm() - seg.omega_norm_bound() * (1.0 + kRoundoff) - kRoundoff});
    if (!(ex <= 0.0) && out.tube_violation < 0.0) out.tube_violation = t;
    out.worst_excess = std::max(out.worst_excess, std::isfinite(ex) ? ex : 1e300);
  }
}

/// The sample at t_i against the ball of step i (the initial ball for i = 0).
void check_ball_at(const ReachResult& res, std::size_t i, double t, const Mat3& Rk, const Vec3& wk,
                   SampleOutcome& out) {
  double ratio;
  if (i == 0) {
    ratio = metric_distance_upper({res.Q0, res.S0, res.P0}, res.nominal[0].R, res.nominal[0].omega, Rk, wk) / res.r0;
  } else {
    const ReachStep& st = res.steps[i - 1];
    ratio = metric_distance_upper(st.metric(), st.R, st.omega, Rk, wk) / st.r;
  }
  if (!(ratio <= 1.0 + kRoundoff) && out.violation < 0.0) out.violation = t;
  out.worst = std::max(out.worst, std::isfinite(ratio) ? ratio : 1e300);
}

/// Simulates one sample from (R, ω) at its cell's nominal times against the cell's tube, U_i
/// and balls.
SampleOutcome check_sample(const ClosedLoop& loop, const ReachResult& res, const PointIndex& ix,
                           const Mat3& R, const Vec3& w, double step, bool keep) {
  SampleOutcome out;
  simulate_stops(loop, 0.0, R, w, ix.times, step, [&](std::size_t k, const Mat3& Rk, const Vec3& wk) {
    if (keep) {
      out.traj.t.push_back(ix.times[k]);
      out.traj.R.push_back(Rk);
      out.traj.omega.push_back(wk);
    }
    check_tube_at(res, ix, k, ix.times[k], Rk, wk, out);
    if (ix.ball[k] < 0) return;
    check_ball_at(res, static_cast<std::size_t>(ix.ball[k]), ix.times[k], Rk, wk, out);
  });
  return out;
}

/// The report's figures over all samples, merged under a lock.
struct SampleTotals {
  std::atomic<long> inside{0};
  std::atomic<long> tube_inside{0};
  std::mutex mutex;
  double tube_excess{0.0};
  double first_tube_violation{-1.0};
  double max_ratio{0.0};
  double first_violation{-1.0};
};

/// Adds one sample's outcome to the totals (and its trajectory to the report when kept).
void merge_sample(SampleTotals& totals, SampleOutcome& o, SoundnessReport& rep, long s, bool keep) {
  if (o.violation < 0.0) ++totals.inside;
  if (o.tube_violation < 0.0) ++totals.tube_inside;
  std::lock_guard<std::mutex> lock(totals.mutex);
  totals.tube_excess = std::max(totals.tube_excess, o.worst_excess);
  if (o.tube_violation >= 0.0 &&
      (totals.first_tube_violation < 0.0 || o.tube_violation < totals.first_tube_violation)) {
    totals.first_tube_violation = o.tube_violation;
  }
  totals.max_ratio = std::max(totals.max_ratio, o.worst);
  if (o.violation >= 0.0 && (totals.first_violation < 0.0 || o.violation < totals.first_violation)) {
    totals.first_violation = o.violation;
  }
  if (keep) rep.kept[static_cast<std::size_t>(s)] = std::move(o.traj);
}

}  // namespace

SoundnessReport check_soundness(const ClosedLoop& loop, const InitialSet& whole,
                                const std::vector<InitialSet>& cells,
                                const std::vector<ReachResult>& results,
                                const SoundnessSettings& settings) {
  const auto wall0 = std::chrono::steady_clock::now();
  if (cells.size() != results.size() || cells.empty()) {
    throw NumericalError("soundness check: cells and results do not match");
  }
  SoundnessReport rep;
  rep.samples = settings.samples;
  std::vector<PointIndex> index;
  for (const ReachResult& res : results) index.push_back(index_points(res));
  SampleTotals totals;
  rep.kept.resize(static_cast<std::size_t>(std::min<long>(settings.keep, settings.samples)));

  std::atomic<long> checked{0};
  parallel::parallel_for(settings.samples, settings.threads, [&](long s) {
    if (settings.stop != nullptr && settings.stop->load(std::memory_order_relaxed)) return;
    std::mt19937_64 g(settings.seed * 0x9E3779B97F4A7C15ULL + static_cast<std::uint64_t>(s));
    const bool boundary = (s % 2) == 0;
    const Mat3 R = whole.R0 * lie::exp(sample_ball(g, whole.attitude_radius, boundary));
    const Vec3 w = whole.omega0 + sample_ball(g, whole.omega_radius, boundary);
    const std::size_t cell = containing_cell(cells, R, w);
    const bool keep = s < static_cast<long>(rep.kept.size());
    SampleOutcome outcome = check_sample(loop, results[cell], index[cell], R, w, settings.step, keep);
    merge_sample(totals, outcome, rep, s, keep);
    ++checked;
  });
  rep.samples = checked.load();
  rep.stopped = rep.samples < settings.samples;
  rep.inside = totals.inside.load();
  rep.max_ratio = totals.max_ratio;
  rep.first_violation_time = totals.first_violation;
  rep.tube_inside = totals.tube_inside.load();
  rep.tube_max_excess = totals.tube_excess;
  rep.tube_first_violation_time = totals.first_tube_violation;
  rep.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  return rep;
}

}  // namespace attiguard::reach
