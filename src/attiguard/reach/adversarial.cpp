#include "attiguard/reach/adversarial.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <mutex>
#include <random>

#include "attiguard/core/errors.hpp"
#include "attiguard/parallel/parallel_for.hpp"
#include "attiguard/reach/metrics.hpp"

namespace attiguard::reach {

namespace {

/// A state on the boundary of a cell's initial set: directions u (attitude) and v (ω).
struct Boundary {
  Vec3 u{Vec3::UnitX()};
  Vec3 v{Vec3::UnitX()};
};

/// What one trajectory scores: the worst ratio over the t_i, and its spread at the last t_i.
struct Score {
  double ratio{0.0};
  double ratio_time{0.0};
  double attitude{0.0};
  Vec3 omega{Vec3::Zero()};
};

Vec3 random_unit(std::mt19937_64& g) {
  std::normal_distribution<double> n(0.0, 1.0);
  Vec3 x(n(g), n(g), n(g));
  while (x.norm() < 1e-12) x = Vec3(n(g), n(g), n(g));
  return x.normalized();
}

Score score(const ClosedLoop& loop, const InitialSet& cell, const ReachResult& res,
            const std::vector<double>& times, const Boundary& b, double step) {
  const Mat3 R0 = cell.R0 * lie::exp(cell.attitude_radius * b.u);
  const Vec3 w0 = cell.omega0 + cell.omega_radius * b.v;
  const std::size_t n = res.steps.size();
  Score s;
  simulate(loop, R0, w0, times, step, [&](std::size_t k, const Mat3& R, const Vec3& w) {
    if (k == 0) return;  // t = 0: the covering ball of the initial set, ratio ≤ 1 by construction
    const ReachStep& st = res.steps[k - 1];
    const double ratio = metric_distance_upper(st.metric(), st.R, st.omega, R, w) / st.r;
    const double r = std::isfinite(ratio) ? ratio : 1e300;
    if (r > s.ratio) {
      s.ratio = r;
      s.ratio_time = times[k];
    }
    if (k == n) {
      s.attitude = lie::distance(res.steps.back().R, R);
      s.omega = (w - res.steps.back().omega).cwiseAbs();
    }
  });
  return s;
}

/// The objectives searched: 0 the ratio, 1 the attitude spread, 2–4 the ω spread per axis.
double objective(const Score& s, int which) {
  if (which == 0) return s.ratio;
  if (which == 1) return s.attitude;
  return s.omega(which - 2);
}

}  // namespace

AdversarialReport adversarial_check(const ClosedLoop& loop, const std::vector<InitialSet>& cells,
                                    const std::vector<ReachResult>& results,
                                    const AdversarialSettings& settings) {
  const auto wall0 = std::chrono::steady_clock::now();
  if (cells.size() != results.size() || cells.empty()) {
    throw NumericalError("adversarial check: cells and results do not match");
  }
  if (settings.starts < 1 || settings.iterations < 0) throw InputError("adversarial check: starts must be >= 1");
  constexpr int kObjectives = 5;
  AdversarialReport rep;
  std::mutex mutex;
  const long jobs = static_cast<long>(cells.size()) * kObjectives * settings.starts;
  std::atomic<bool> stopped{false};
  parallel::parallel_for(jobs, settings.threads, [&](long job) {
    if (settings.stop != nullptr && settings.stop->load(std::memory_order_relaxed)) {
      stopped = true;
      return;
    }
    const auto cell = static_cast<std::size_t>(job / (kObjectives * settings.starts));
    const int which = static_cast<int>((job / settings.starts) % kObjectives);
    const ReachResult& res = results[cell];
    std::vector<double> times{0.0};
    for (const ReachStep& st : res.steps) times.push_back(st.t1);
    std::mt19937_64 g(settings.seed * 0x9E3779B97F4A7C15ULL + static_cast<std::uint64_t>(job));
    Boundary best{random_unit(g), random_unit(g)};
    Score best_score = score(loop, cells[cell], res, times, best, settings.step);
    double radius = 0.5;  // perturbation size on the spheres
    long evaluations = 1;
    std::normal_distribution<double> n(0.0, 1.0);
    for (int it = 0; it < settings.iterations; ++it) {
      Boundary cand{(best.u + radius * Vec3(n(g), n(g), n(g))).normalized(),
                    (best.v + radius * Vec3(n(g), n(g), n(g))).normalized()};
      if (!cand.u.allFinite() || !cand.v.allFinite()) continue;
      const Score s = score(loop, cells[cell], res, times, cand, settings.step);
      ++evaluations;
      if (objective(s, which) > objective(best_score, which)) {
        best = cand;
        best_score = s;
        radius = std::min(1.0, radius * 1.5);
      } else {
        radius = std::max(1e-4, radius * 0.8);
      }
    }
    std::lock_guard<std::mutex> lock(mutex);
    rep.evaluations += evaluations;
    if (best_score.ratio > rep.worst_ratio) {
      rep.worst_ratio = best_score.ratio;
      rep.worst_ratio_time = best_score.ratio_time;
    }
    if (cell == 0) {
      rep.attitude_spread = std::max(rep.attitude_spread, best_score.attitude);
      rep.omega_spread = rep.omega_spread.cwiseMax(best_score.omega);
    }
  });
  rep.stopped = stopped.load();
  if (!results.front().steps.empty()) {
    rep.attitude_claimed = results.front().steps.back().attitude_radius;
    rep.omega_claimed = results.front().steps.back().omega_half_widths;
  }
  rep.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  return rep;
}

}  // namespace attiguard::reach
