#include "attiguard/plan/slew_planner.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <sstream>

#include "attiguard/core/errors.hpp"
#include "attiguard/dynamics/eigenaxis_slew.hpp"
#include "attiguard/plan/cone_quadratic.hpp"
#include "attiguard/plan/initial_path.hpp"
#include "attiguard/plan/transcription_nlp.hpp"

namespace attiguard::plan {

namespace {

using lie::Quat;

constexpr double kRadToDeg = 180.0 / std::numbers::pi;
/// The program keeps its torque and cone constraints this much inside the plan's own (relative
/// torque; angle in rad), so that IPOPT's constraint tolerance (10⁻⁹) never crosses them.
constexpr double kInside = 1e-7;
/// A cone is left out of the program at the points where the initial guess keeps it with this
/// much beyond the margin (docs/slew-planner.md, "Speed") [rad].
constexpr double kPruneAngle = 30.0 * std::numbers::pi / 180.0;
/// IPOPT's tolerance in the screening's coarse solves: their durations are compared and seed the
/// fine solve, nothing else (docs/slew-planner.md, "Speed").
constexpr double kScreenTolerance = 1e-6;

/// The scales of the program (docs/slew-planner.md, "Scaling"): time t_s, torque τ_s.
struct Scales {
  double time{1.0};
  double torque{1.0};
};

/// Rest-to-rest eigenaxis bang-bang along each segment of `path` at the torque `tau` (each
/// segment's own time 2√(θ‖Jk‖/τ)), sampled on the transcription's uniform grid: the initial
/// guess (docs/slew-planner.md, "The initial path").
TranscriptionValues initial_guess(const AttitudePath& path, const SlewProblem& problem,
                                  const TranscriptionSetup& setup, Scales& scales) {
  struct Segment {
    Quat q_from;
    lie::Vec3 axis_b;
    double angle, duration, start;
  };
  const double tau = 0.8 * scales.torque;
  std::vector<Segment> segments;
  double total = 0.0;
  for (std::size_t i = 0; i + 1 < path.waypoints.size(); ++i) {
    Quat rel = lie::quat_multiply(lie::quat_conjugate(path.waypoints[i]), path.waypoints[i + 1]);
    if (rel(0) < 0.0) rel = -rel;
    const lie::Vec3 w = lie::rotation_vector_from_quat(rel);
    const double angle = w.norm();
    const lie::Vec3 axis = angle > 0.0 ? lie::Vec3(w / angle) : lie::Vec3::UnitX();
    const double duration = angle > 0.0 ? 2.0 * std::sqrt(angle * (problem.J_b * axis).norm() / tau) : 0.0;
    segments.push_back({path.waypoints[i], axis, angle, duration, total});
    total += duration;
  }
  if (!(total > 0.0)) total = 1.0;  // R_0 = R_d: a zero slew, any scale
  scales.time = total;
  const int points = transcription_points(setup.transcription, setup.intervals);
  TranscriptionValues out;
  out.duration = 1.0;
  for (int p = 0; p < points; ++p) {
    const double t = total * p / (points - 1);
    std::size_t s = 0;
    while (s + 1 < segments.size() && t > segments[s].start + segments[s].duration) ++s;
    const Segment& seg = segments[s];
    const double local = std::clamp(t - seg.start, 0.0, seg.duration);
    double angle = 0.0, rate = 0.0, accel = 0.0;
    if (seg.duration > 0.0) {
      const double a = 4.0 * seg.angle / (seg.duration * seg.duration);
      if (local < 0.5 * seg.duration) {
        angle = 0.5 * a * local * local;
        rate = a * local;
        accel = a;
      } else {
        const double rest = seg.duration - local;
        angle = seg.angle - 0.5 * a * rest * rest;
        rate = a * rest;
        accel = -a;
      }
    }
    const lie::Vec3 omega = rate * seg.axis_b;
    const lie::Vec3 u = problem.J_b * (accel * seg.axis_b) + omega.cross(problem.J_b * omega);
    PointVector z;
    z.head<4>() = lie::quat_multiply(seg.q_from, lie::quat_from_rotation_vector(angle * seg.axis_b));
    z.segment<3>(4) = omega * scales.time;
    z.segment<3>(7) = (u / scales.torque).cwiseMax(-1.0).cwiseMin(1.0);
    out.points.push_back(z);
  }
  return out;
}

/// The coarse plan of the screening (docs/slew-planner.md, "Speed") sampled on the finer
/// transcription's uniform grid: the initial guess of the fine solve. Sets the time scale to the
/// coarse plan's duration (T̄ = 1).
TranscriptionValues guess_from_plan(const governor::SlewPlan& coarse, const TranscriptionSetup& setup,
                                    Scales& scales) {
  scales.time = coarse.duration();
  const int points = transcription_points(setup.transcription, setup.intervals);
  TranscriptionValues out;
  out.duration = 1.0;
  for (int p = 0; p < points; ++p) {
    const governor::SlewPlanSample s = coarse.evaluate(scales.time * p / (points - 1));
    PointVector z;
    z.head<4>() = s.q_ib;
    z.segment<3>(4) = s.omega_b * scales.time;
    z.segment<3>(7) = (s.tau_b / scales.torque).cwiseMax(-1.0).cwiseMin(1.0);
    out.points.push_back(z);
  }
  return out;
}

/// The plan in SI units from the scaled values: the nodes of the transcription (for
/// Hermite–Simpson the even points; its midpoints lie on the same cubics).
governor::SlewPlan to_plan(const TranscriptionValues& values, const TranscriptionSetup& setup,
                           const Scales& scales, const SlewProblem& problem) {
  const PointDynamics dynamics(setup.J_scaled);
  const int stride = setup.transcription == Transcription::hermite_simpson ? 2 : 1;
  std::vector<governor::SlewPlanNode> nodes;
  std::vector<lie::Vec3> midpoint_torques;
  const double duration = values.duration * scales.time;
  for (int k = 0; k <= setup.intervals; ++k) {
    const PointVector& z = values.points[static_cast<std::size_t>(k * stride)];
    governor::SlewPlanNode n;
    n.t = duration * k / setup.intervals;
    n.q_ib = z.head<4>();
    n.omega_b = z.segment<3>(4) / scales.time;
    n.omega_dot_b = dynamics.f(z).segment<3>(4) / (scales.time * scales.time);
    n.tau_b = z.segment<3>(7) * scales.torque;
    nodes.push_back(n);
    if (stride == 2 && k < setup.intervals) {
      midpoint_torques.push_back(values.points[static_cast<std::size_t>(2 * k + 1)].segment<3>(7) *
                                 scales.torque);
    }
  }
  return governor::SlewPlan(std::move(nodes), std::move(midpoint_torques), problem.J_b);
}

/// Per interval: the smallest margin of each cone and the largest torque ratio.
struct IntervalCheck {
  std::vector<std::vector<double>> cone_margin;  ///< [interval][cone] [rad]
  std::vector<double> torque_ratio;              ///< [interval]
  DenseCheck overall;
};

/// The rigid body's state for the dense check's consistency integration.
struct BodyState {
  Quat q;
  lie::Vec3 omega_b;
};

/// ẋ of the rigid body ([Waypoint eqs. (4)-(5)]; [PET-ERG eq. (1)]) under the plan's torque.
BodyState body_rate(const BodyState& x, const governor::SlewPlan& plan, int k, double t) {
  const lie::Mat3& J = plan.inertia();
  const lie::Vec3 tau = plan.evaluate_in(k, t).tau_b;
  BodyState d;
  d.q(0) = -0.5 * x.q.tail<3>().dot(x.omega_b);
  d.q.tail<3>() = 0.5 * (x.q(0) * x.omega_b + x.q.tail<3>().cross(x.omega_b));
  d.omega_b = J.ldlt().solve(tau - x.omega_b.cross(J * x.omega_b));
  return d;
}

/// One classical RK4 step of the rigid body under the plan's torque within interval k.
BodyState rk4_step(const BodyState& x, const governor::SlewPlan& plan, int k, double t, double h) {
  auto add = [](const BodyState& a, const BodyState& d, double s) {
    return BodyState{a.q + s * d.q, a.omega_b + s * d.omega_b};
  };
  const BodyState k1 = body_rate(x, plan, k, t);
  const BodyState k2 = body_rate(add(x, k1, 0.5 * h), plan, k, t + 0.5 * h);
  const BodyState k3 = body_rate(add(x, k2, 0.5 * h), plan, k, t + 0.5 * h);
  const BodyState k4 = body_rate(add(x, k3, h), plan, k, t + h);
  return BodyState{x.q + h / 6.0 * (k1.q + 2.0 * k2.q + 2.0 * k3.q + k4.q),
                   x.omega_b + h / 6.0 * (k1.omega_b + 2.0 * k2.omega_b + 2.0 * k3.omega_b + k4.omega_b)};
}

IntervalCheck check_intervals(const governor::SlewPlan& plan, const SlewProblem& problem,
                              int points_per_interval) {
  IntervalCheck out;
  const int N = plan.intervals();
  const std::size_t n_cones = problem.cones.size();
  out.cone_margin.assign(static_cast<std::size_t>(N),
                         std::vector<double>(n_cones, std::numeric_limits<double>::max()));
  out.torque_ratio.assign(static_cast<std::size_t>(N), 0.0);
  out.overall.smallest_cone_margin = std::numeric_limits<double>::max();
  const auto nodes = plan.nodes();
  for (int k = 0; k < N; ++k) {
    const double ta = nodes[static_cast<std::size_t>(k)].t;
    const double tb = nodes[static_cast<std::size_t>(k + 1)].t;
    BodyState flown{nodes[static_cast<std::size_t>(k)].q_ib.normalized(),
                    nodes[static_cast<std::size_t>(k)].omega_b};
    for (int i = 0; i <= points_per_interval; ++i) {
      const double t = ta + (tb - ta) * i / points_per_interval;
      const governor::SlewPlanSample s = plan.evaluate_in(k, t);
      if (i > 0) {
        flown = rk4_step(flown, plan, k, t - (tb - ta) / points_per_interval, (tb - ta) / points_per_interval);
        const double deviation = 2.0 * std::acos(std::min(1.0, std::abs(flown.q.normalized().dot(s.q_ib))));
        out.overall.largest_attitude_deviation = std::max(out.overall.largest_attitude_deviation, deviation);
      }
      const double ratio = s.tau_b.norm() / problem.tau_max;
      double& worst_ratio = out.torque_ratio[static_cast<std::size_t>(k)];
      worst_ratio = std::max(worst_ratio, ratio);
      if (ratio > out.overall.largest_torque_ratio) {
        out.overall.largest_torque_ratio = ratio;
        out.overall.largest_torque_time = t;
      }
      for (std::size_t c = 0; c < n_cones; ++c) {
        const double m = cone_angle_margin(problem.cones[c], s.R_ib);
        double& worst = out.cone_margin[static_cast<std::size_t>(k)][c];
        worst = std::min(worst, m);
        if (m < out.overall.smallest_cone_margin) {
          out.overall.smallest_cone_margin = m;
          out.overall.smallest_margin_cone = static_cast<int>(c);
          out.overall.smallest_margin_time = t;
        }
      }
    }
  }
  return out;
}

/// Refuses (exit 4) an end attitude that does not keep every cone with the margin.
void require_end_keeps_cones(const SlewProblem& problem, const lie::Mat3& R, const char* which) {
  for (std::size_t c = 0; c < problem.cones.size(); ++c) {
    const double m = cone_angle_margin(problem.cones[c], R);
    if (m < problem.cone_margin) {
      std::ostringstream msg;
      msg.precision(4);
      msg << "plan: no admissible path: the " << which << " attitude does not keep cones[" << c
          << "] (its axis is " << (m < 0.0 ? -m : m) * kRadToDeg << " deg "
          << (m < 0.0 ? "inside the forbidden side" : "from the cone's edge") << ", the plan needs "
          << problem.cone_margin * kRadToDeg << " deg of margin)";
      throw VerificationFailure(msg.str());
    }
  }
}

/// Per cone and point: whether the cone is imposed there (docs/slew-planner.md, "Speed").
using ConeRows = std::vector<std::vector<bool>>;

/// The cones imposed at each point: those the guess passes within kPruneAngle of (their
/// boundary, beyond the margin); the others are left out of the program until a dense check
/// finds the plan near them.
ConeRows far_from_guess(const TranscriptionValues& guess, const SlewProblem& problem, int points) {
  ConeRows rows(problem.cones.size(), std::vector<bool>(static_cast<std::size_t>(points), true));
  for (int p = 0; p < points; ++p) {
    const lie::Mat3 R = lie::quat_to_rotation(guess.points[static_cast<std::size_t>(p)].head<4>().normalized());
    for (std::size_t c = 0; c < problem.cones.size(); ++c) {
      const double margin = cone_angle_margin(problem.cones[c], R) - problem.cone_margin;
      rows[c][static_cast<std::size_t>(p)] = margin < kPruneAngle;
    }
  }
  return rows;
}

/// The cosine each imposed cone must keep at each point: the margin, kInside and the point's
/// tightening; −∞ (not imposed) where `rows` leaves it out.
void set_cone_levels(TranscriptionSetup& setup, const SlewProblem& problem,
                     const std::vector<std::vector<double>>& tightening, const ConeRows& rows) {
  for (std::size_t c = 0; c < problem.cones.size(); ++c) {
    auto& cosine = setup.cones[c].cosine_at_point;
    cosine.resize(rows[c].size());
    for (std::size_t p = 0; p < cosine.size(); ++p) {
      cosine[p] = rows[c][p] ? tightened_cosine(problem.cones[c],
                                                problem.cone_margin + kInside + tightening[c][p])
                             : -std::numeric_limits<double>::infinity();
    }
  }
}

/// What a dense check says of a solve.
enum class Verdict {
  pass,             ///< every cone kept with its margin
  tighten,          ///< some interval misses a margin: its points are tightened
  pruned_too_much,  ///< the plan came near a cone left out: it is imposed everywhere again
};

/// Judges the dense check's cone margins (docs/slew-planner.md, "Between the nodes"): a miss in
/// an interval where the cone was left out imposes that cone at every point; a miss where it
/// was imposed tightens the interval's points by 1.5× the deficit.
Verdict judge(const IntervalCheck& check, const SlewProblem& problem, int stride,
              std::vector<std::vector<double>>& tightening, ConeRows& rows) {
  Verdict verdict = Verdict::pass;
  const int intervals = static_cast<int>(check.cone_margin.size());
  for (std::size_t c = 0; c < problem.cones.size(); ++c) {
    bool left_out_missed = false;
    for (int k = 0; k < intervals; ++k) {
      const double deficit = problem.cone_margin - check.cone_margin[static_cast<std::size_t>(k)][c];
      // Near a left-out cone (within a tenth of the pruning angle) counts as a miss too.
      bool was_left_out = false;
      for (int p = k * stride; p <= (k + 1) * stride; ++p) was_left_out |= !rows[c][static_cast<std::size_t>(p)];
      if (was_left_out && deficit > -0.1 * kPruneAngle) {
        left_out_missed = true;
        continue;
      }
      if (deficit <= 0.0) continue;
      if (verdict == Verdict::pass) verdict = Verdict::tighten;
      for (int p = k * stride; p <= (k + 1) * stride; ++p) {
        tightening[c][static_cast<std::size_t>(p)] += 1.5 * deficit + 1e-6;
      }
    }
    if (left_out_missed) {
      rows[c].assign(rows[c].size(), true);
      verdict = Verdict::pruned_too_much;
    }
  }
  return verdict;
}

/// One way around the cones refined until its dense check passes: the plan, or the failure.
struct Refined {
  bool ok{false};      ///< the dense check passed
  bool solved{false};  ///< IPOPT solved at least once (`plan` is its last solution)
  governor::SlewPlan plan;
  DenseCheck check;
  std::string status;
  std::string failure;
  int solves{0};
  int iterations{0};
  int reimposed{0};  ///< re-solves after a left-out cone was approached
};

Refined refine(const AttitudePath& path, const SlewProblem& problem, const PlannerOptions& options,
               int intervals, const governor::SlewPlan* coarse = nullptr,
               double tolerance = TranscriptionSetup{}.tolerance) {
  Refined out;
  TranscriptionSetup setup;
  setup.transcription = options.transcription;
  setup.intervals = intervals;
  setup.max_iterations = options.max_iterations;
  setup.max_seconds = options.max_solve_seconds;
  setup.tolerance = tolerance;
  Scales scales;
  scales.torque = (1.0 - problem.torque_headroom) * problem.tau_max;
  setup.q_start = path.waypoints.front();
  setup.q_target = path.waypoints.back();
  TranscriptionValues values = coarse != nullptr ? guess_from_plan(*coarse, setup, scales)
                                                 : initial_guess(path, problem, setup, scales);
  setup.J_scaled = problem.J_b / (scales.torque * scales.time * scales.time);
  setup.max_duration = 20.0;
  const int points = transcription_points(setup.transcription, intervals);
  const int stride = setup.transcription == Transcription::hermite_simpson ? 2 : 1;
  // δ_p per cone: the tightening beyond the margin at each point (docs/slew-planner.md,
  // "Between the nodes").
  std::vector<std::vector<double>> tightening(problem.cones.size(),
                                              std::vector<double>(static_cast<std::size_t>(points), 0.0));
  for (std::size_t c = 0; c < problem.cones.size(); ++c) {
    setup.cones.push_back({cone_quadratic(problem.cones[c].axis_b, problem.cones[c].direction_i), {}});
  }
  const double torque_target = 1.0 - problem.torque_headroom;
  setup.torque_limit = 1.0 - kInside;
  ConeRows rows = far_from_guess(values, problem, points);
  for (int round = 0; round <= options.max_refinements;) {
    set_cone_levels(setup, problem, tightening, rows);
    const TranscriptionResult solved = solve_transcription(setup, values);
    ++out.solves;
    out.iterations += solved.iterations;
    out.status = solved.status;
    if (!solved.solved) {
      out.failure = "IPOPT stopped with status " + solved.status;
      return out;
    }
    out.solved = true;
    values = solved.values;
    out.plan = to_plan(values, setup, scales, problem);
    const IntervalCheck check = check_intervals(out.plan, problem, options.dense_points_per_interval);
    out.check = check.overall;
    const Verdict verdict = judge(check, problem, stride, tightening, rows);
    if (verdict == Verdict::pruned_too_much) {  // not a refinement: the same program
      ++out.reimposed;
      continue;
    }
    if (verdict == Verdict::pass && check.overall.largest_torque_ratio <= torque_target) {
      out.ok = true;
      return out;
    }
    if (check.overall.largest_torque_ratio > torque_target) {
      setup.torque_limit *= torque_target / check.overall.largest_torque_ratio * (1.0 - 1e-4);
    }
    ++round;
  }
  std::ostringstream msg;
  msg.precision(4);
  msg << "the dense check still fails after " << options.max_refinements
      << " refinements (smallest cone margin " << out.check.smallest_cone_margin * kRadToDeg
      << " deg, largest |tau|/tau_max " << out.check.largest_torque_ratio << ")";
  out.failure = msg.str();
  return out;
}

/// N: 24 for the eigenaxis, 8 more per further segment of the path, even (the eigenaxis
/// bang-bang switch then falls on a node), at most 64 (docs/slew-planner.md, "Options").
int derived_intervals(const AttitudePath& path) {
  const int segments = static_cast<int>(path.waypoints.size()) - 1;
  return std::min(64, 24 + 8 * (segments - 1));
}

/// The screening of the ways around the cones (docs/slew-planner.md, "Speed").
struct Screening {
  std::vector<bool> kept;                                ///< [way] solved finely
  std::vector<std::optional<governor::SlewPlan>> coarse;  ///< [way] its coarse plan, if solved
  int solves{0};
  int iterations{0};
};

/// With more than one way, each is solved once on a mesh of a quarter of its intervals (at least
/// 8), without the dense check's re-solves; the ways whose coarse duration is within
/// kScreenTolerance of the best are kept, as are those whose coarse solve failed (nothing is
/// known of them). With one way, it is kept and nothing is solved.
Screening screen_ways(const std::vector<AttitudePath>& paths, const std::vector<int>& intervals,
                      const SlewProblem& problem, const PlannerOptions& options) {
  Screening out;
  out.kept.assign(paths.size(), true);
  out.coarse.resize(paths.size());
  if (paths.size() < 2) return out;
  PlannerOptions coarse_options = options;
  coarse_options.max_refinements = 0;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < paths.size(); ++i) {
    const int coarse_intervals = std::max(8, intervals[i] / 8 * 2);
    Refined r = refine(paths[i], problem, coarse_options, coarse_intervals, nullptr, kScreenTolerance);
    out.solves += r.solves;
    out.iterations += r.iterations;
    if (r.solved) {
      best = std::min(best, r.plan.duration());
      out.coarse[i] = std::move(r.plan);
    }
  }
  // The first way of the least coarse duration; the others stay the fallback.
  bool chosen = false;
  for (std::size_t i = 0; i < paths.size(); ++i) {
    out.kept[i] = !chosen && out.coarse[i] && out.coarse[i]->duration() == best;
    chosen = chosen || out.kept[i];
  }
  if (!chosen) out.kept.assign(paths.size(), true);  // no coarse solve succeeded: all, cold
  return out;
}

}  // namespace

DenseCheck dense_check(const governor::SlewPlan& plan, const SlewProblem& problem,
                       int points_per_interval) {
  return check_intervals(plan, problem, points_per_interval).overall;
}

PlannedSlew plan_slew(const SlewProblem& problem, const PlannerOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  if (auto e = slew_problem_error(problem, options)) throw SetupError("plan: " + *e);
  require_end_keeps_cones(problem, problem.R_start, "start");
  require_end_keeps_cones(problem, problem.R_target, "target");
  const PathSearch search = find_paths(problem, options.try_both_sides ? 2 : 1);
  if (search.paths.empty()) {
    std::ostringstream msg;
    msg << "plan: no admissible path: the cones close every way the search tried ("
        << search.attitudes << " attitudes, " << search.segments_checked
        << " eigenaxis segments checked)";
    throw VerificationFailure(msg.str());
  }
  const std::size_t n_ways = search.paths.size();
  std::vector<int> intervals(n_ways);
  for (std::size_t i = 0; i < n_ways; ++i) {
    intervals[i] = options.intervals > 0 ? options.intervals : derived_intervals(search.paths[i]);
  }
  int solves = 0, iterations = 0, reimposed = 0;
  const Screening screening = screen_ways(search.paths, intervals, problem, options);
  solves += screening.solves;
  iterations += screening.iterations;
  PlannedSlew best;
  bool have = false;
  std::string failures;
  // The ways the screening kept, from their coarse plans; the others only if none of those gives
  // a plan (then from the roadmap's path, as without screening).
  for (const bool kept_pass : {true, false}) {
    if (have) break;
    for (std::size_t i = 0; i < n_ways; ++i) {
      if (screening.kept[i] != kept_pass) continue;
      const governor::SlewPlan* coarse =
          kept_pass && screening.coarse[i] ? &*screening.coarse[i] : nullptr;
      Refined r = refine(search.paths[i], problem, options, intervals[i], coarse);
      solves += r.solves;
      iterations += r.iterations;
      reimposed += r.reimposed;
      if (!r.ok) {
        failures += (failures.empty() ? "" : "; ") + r.failure;
        continue;
      }
      if (!have || r.plan.duration() < best.plan.duration()) {
        best.plan = std::move(r.plan);
        best.report.check = r.check;
        best.report.solver_status = r.status;
        best.report.intervals = intervals[i];
        best.report.path_waypoints = static_cast<int>(search.paths[i].waypoints.size()) - 2;
        have = true;
      }
    }
  }
  if (!have) throw NumericalError("plan: no plan: " + failures);
  PlanReport& report = best.report;
  report.duration = best.plan.duration();
  report.bang_bang_time = dynamics::eigenaxis_bang_bang_time(problem.J_b, problem.R_start,
                                                             problem.R_target, problem.tau_max);
  report.ratio = report.bang_bang_time > 0.0 ? report.duration / report.bang_bang_time : 0.0;
  report.ways_tried = static_cast<int>(search.paths.size());
  report.solves = solves;
  report.iterations = iterations;
  report.cones_reimposed = reimposed;
  report.roadmap_attitudes = search.attitudes;
  report.planning_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return best;
}

}  // namespace attiguard::plan
