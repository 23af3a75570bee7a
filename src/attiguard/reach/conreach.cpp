#include "attiguard/reach/conreach.hpp"

#include <algorithm>
#include <chrono>
#include <optional>
#include <limits>
#include <span>
#include <cmath>
#include <numbers>
#include <sstream>

#include "attiguard/core/errors.hpp"
#include "attiguard/reach/dense_sdp.hpp"
#include "attiguard/reach/metrics.hpp"
#include "attiguard/reach/proved_radii.hpp"
#include "attiguard/reach/scalar_interval.hpp"

namespace attiguard::reach {

namespace {

void check_settings(const InitialSet& init, const ConReachSettings& s) {
  auto bad = [](const std::string& m) { throw InputError("reach: " + m); };
  if (!(s.horizon > 0.0) || !std::isfinite(s.horizon)) bad("horizon must be a positive number");
  if (s.steps < 1) bad("steps must be >= 1");
  if (s.substeps < 1) bad("substeps must be >= 1");
  if (!s.adaptive && !(s.integrator_step > 0.0)) bad("integrator_step must be positive");
  if (!(s.integrator_step <= s.horizon) || !std::isfinite(s.integrator_step)) bad("integrator_step must not exceed the horizon");
  if (s.max_bisections < 0 || s.max_bisections > 30) bad("max_bisections must be in [0, 30]");
  if (s.max_adaptive_steps < 1) bad("max_adaptive_steps must be >= 1");
  if (s.line_search_steps < 1) bad("line_search_steps must be >= 1");
  if (!(s.rate_step > 0.0)) bad("rate_step must be positive");
  if (!(s.attitude_floor_ratio > 0.0 && s.attitude_floor_ratio <= 1.0)) {
    bad("attitude_floor_ratio must be in (0, 1]");
  }
  if (!init.R0.allFinite() || !lie::is_rotation(init.R0, 1e-9)) bad("initial attitude is not a rotation");
  if (!init.omega0.allFinite()) bad("initial omega_b is not finite");
  if (!(init.attitude_radius >= 0.0) || !(init.attitude_radius < std::numbers::pi)) {
    bad("initial attitude_radius must be in [0, pi)");
  }
  if (!(init.omega_radius >= 0.0) || !std::isfinite(init.omega_radius)) {
    bad("initial omega_radius must be a non-negative number");
  }
  if (init.attitude_radius + init.omega_radius <= 0.0) bad("the initial set must not be a single point");
  require_spd(init.P0, "reach: initial metric P0");
}

struct Choice {
  MetricSolution sol;
  std::vector<RateTrial> trials;
  bool fallback{false};
  int solves{0};
  double c_identity{0.0};
};

/// Product metric: the paper's line search or the min-enclosure scan (docs/reach.md, "Rate
/// selection"). `size_of` maps a solution to the bi-invariant enclosure radius of its ball.
Choice choose_product(const LmiEnclosure& enc, const StateMetric& prev, const ConReachSettings& s,
                      const MetricSdpSettings& sdp,
                      const std::function<double(const MetricSolution&)>& size_of) {
  Choice ch;
  ch.c_identity = identity_metric_rate(enc);
  bool have = false;
  if (s.mode == RateMode::line_search) {
    for (int j = 0; j < s.line_search_steps; ++j) {
      const double c = ch.c_identity - j * s.rate_step;
      MetricSolution m = solve_metric(enc, prev, c, MetricObjective::max_trace_q, sdp);
      ++ch.solves;
      const bool diag_ok = m.ok && m.Q.diagonal().minCoeff() >= s.min_diagonal &&
                           m.P.diagonal().minCoeff() >= s.min_diagonal;
      ch.trials.push_back({c, m.ok, m.ok ? size_of(m) : 0.0});
      if (!diag_ok) break;
      ch.sol = m;
      have = true;
    }
  } else {
    double best = std::numeric_limits<double>::infinity();
    int worse = 0;  // consecutive candidates worse than the best: stop after 2
    for (int j = 0; j < s.min_enclosure_candidates && worse < 2; ++j) {
      const double c = ch.c_identity - j * s.rate_step;
      MetricSolution m = solve_metric(enc, prev, c, MetricObjective::max_min_eigenvalue, sdp);
      ++ch.solves;
      ch.trials.push_back({c, m.ok, m.ok ? size_of(m) : 0.0});
      if (!m.ok) break;
      if (size_of(m) < best) {
        best = size_of(m);
        ch.sol = m;
        have = true;
        worse = 0;
      } else {
        ++worse;
      }
    }
    const MetricSolution fb = fallback_metric(enc, prev, sdp.rigorous);
    if (fb.ok && (!have || size_of(fb) < best)) {
      ch.sol = fb;
      ch.fallback = true;
      have = true;
    }
  }
  if (!have) {
    ch.sol = fallback_metric(enc, prev, sdp.rigorous);
    ch.fallback = true;
  }
  return ch;
}

/// Coupled metric: a golden-section search of the rate minimising the enclosure radius
/// (max_min_eigenvalue objective). The feasible rates form [c_min, ∞) (L(M, c) decreases with c),
/// so +∞ (infeasible) on the left of the bracket moves it right. First step: the bracket
/// [c_max − (2|c_max| + 1), c_max], 12 iterations; later steps: around the previous rate,
/// [c_prev − w, c_prev + w], w = 0.2 + 0.5|c_prev|, 7 iterations, and the first step's search
/// when no rate of that bracket is accepted. The fallback competes too
/// (docs/reach.md, "Coupled metrics", rate selection).
Choice choose_coupled(const LmiEnclosure& enc, const StateMetric& prev, const MetricSdpSettings& sdp,
                      const std::function<double(const MetricSolution&)>& size_of,
                      const double* c_prev) {
  Choice ch;
  ch.c_identity = identity_metric_rate(enc);
  double best = std::numeric_limits<double>::infinity();
  auto trial = [&](double c) {
    MetricSolution m = solve_metric(enc, prev, c, MetricObjective::max_min_eigenvalue, sdp);
    ++ch.solves;
    const double size = m.ok ? size_of(m) : std::numeric_limits<double>::infinity();
    ch.trials.push_back({c, m.ok, m.ok ? size : 0.0});
    if (m.ok && size < best) {
      best = size;
      ch.sol = m;
    }
    return size;
  };
  auto golden = [&](double a, double b, int iterations) {
    constexpr double g = 0.6180339887498949;
    double x1 = b - g * (b - a);
    double x2 = a + g * (b - a);
    double f1 = trial(x1);
    double f2 = trial(x2);
    for (int it = 0; it < iterations; ++it) {
      if (std::isfinite(f1) && f1 <= f2) {
        b = x2;
        x2 = x1;
        f2 = f1;
        x1 = b - g * (b - a);
        f1 = trial(x1);
      } else {
        a = x1;
        x1 = x2;
        f1 = f2;
        x2 = a + g * (b - a);
        f2 = trial(x2);
      }
    }
  };
  if (c_prev != nullptr) {
    const double w = 0.2 + 0.5 * std::abs(*c_prev);
    golden(*c_prev - w, *c_prev + w, 7);
  }
  if (!std::isfinite(best)) {
    golden(ch.c_identity - (2.0 * std::abs(ch.c_identity) + 1.0), ch.c_identity, 12);
  }
  const MetricSolution fb = fallback_metric(enc, prev, sdp.rigorous);
  if (fb.ok && (!std::isfinite(best) || size_of(fb) < best)) {
    ch.sol = fb;
    ch.fallback = true;
  }
  return ch;
}

Choice choose_metric(const LmiEnclosure& enc, const StateMetric& prev, const ConReachSettings& s,
                     const MetricSdpSettings& sdp,
                     const std::function<double(const MetricSolution&)>& size_of,
                     const double* c_prev) {
  Choice ch = s.metric == MetricKind::coupled ? choose_coupled(enc, prev, sdp, size_of, c_prev)
                                              : choose_product(enc, prev, s, sdp, size_of);
  if (!ch.sol.ok && sdp.rigorous) {
    throw VerificationFailure("ConReach: no metric of the step can be proved rigorously (" +
                              ch.sol.message + ")");
  }
  if (!ch.sol.ok) throw NumericalError("ConReach: no certified contraction metric (" + ch.sol.message + ")");
  return ch;
}

/// The bi-invariant enclosure radius of B_M(x, r): r/√min(λ_min(Q − SP⁻¹Sᵀ), λ_min(P − SᵀQ⁻¹S)).
double enclosure_radius(const StateMetric& m, double r) {
  return r / std::sqrt(std::min(lambda_min(attitude_schur(m)), lambda_min(omega_schur(m))));
}

/// Deviation bounds (deviation.hpp) of every state in B_M(x, r): the projections of coupled
/// facts 2, 3, proved for the floats (proved_radii.hpp).
Deviation ball_deviation(const StateMetric& m, double r) {
  Deviation d;
  d.d_omega_b = proved_omega_half_widths(m, r);
  d.e_omega_b = proved_projection_radius(m, r, StateBlock::omega);
  d.e_R = proved_projection_radius(m, r, StateBlock::attitude);
  return d;
}

/// What every step of one run shares.
struct RunFrame {
  const ClosedLoop& loop;
  const ConReachSettings& s;
  double a;      ///< attitude_radius of the initial set
  double b;      ///< omega_radius of the initial set
  bool coupled;  ///< MetricKind::coupled
  bool att_dep;  ///< the loop's LMI depends on R
  /// The dense SDP solver's warm start, carried from solve to solve of this run (issue 48,
  /// docs/reach.md "Dense SDP solver"); owned by run_conreach.
  DenseSdpWorkspace* warm;
};

/// One step's time grid: t_i, its sub-step boundaries and t_{i+1}; `dt` the length the ball's
/// growth e^{cΔt} uses (T/N on the fixed grid, as it always was; t_{i+1} − t_i when adaptive).
struct StepGrid {
  std::vector<double> times;
  double dt{0.0};
  double h{0.0};  ///< RKMK4 step of the nominal
};

/// Coupled metric, step 0: the radius r_0' = metric_cover_radius(M_1, a, b) of the initial set
/// re-expressed in the step's own metric (docs/reach.md, "Coupled metrics").
double recovered_radius(const RunFrame& f, const MetricSolution& sol) {
  return proved_cover_radius({sol.Q, sol.S, sol.P}, f.a, f.b);
}

/// The deviation the LMI tube U_i starts from: the flowed curves — coupled: at step 0 the
/// straight curves in the initial set (its state tube), later the M_i-geodesics from the centre,
/// inside B_{M_i}(x_i, r_i) (coupled fact 4); product: the ball's ω bounds unless the ω-flow is
/// affine, and the attitude radius r_i/√q_floor when the LMI depends on R.
Deviation lmi_deviation(const RunFrame& f, int i, const Deviation& z_state, const Deviation& ball,
                        double r, double q_floor) {
  Deviation z_lmi = z_state;
  if (f.coupled) {
    if (i > 0) z_lmi = ball;
  } else {
    if (!f.loop.omega_flow_affine()) {
      z_lmi.d_omega_b = ball.d_omega_b;
      z_lmi.e_omega_b = ball.e_omega_b;
    }
    // rounding site: lmi-attitude-floor — r/√q_floor rounded up (q_floor ≤ λ_min(Q) is proved).
    if (f.att_dep) z_lmi.e_R = radius_over_sqrt_up(r, q_floor);
  }
  return z_lmi;
}

/// The metric of one step and the LMI tube U_i it was certified on.
struct StepChoice {
  Choice choice;
  TubeResult lmi_tube;
  bool lmi_exact{false};
  double lmi_rho{0.0};
};

/// The state tube of a step and the ball it started from.
struct StepStart {
  std::vector<NominalPoint> points;  ///< the step's nominal points (m + 1)
  Deviation ball;                    ///< bounds of B_{M_i}(x_i, r_i)
  Deviation z_state;                 ///< the state tube's start
  TubeResult state_tube;
};

/// choose_metric, with a VerificationFailure naming the step and its interval.
Choice choose_step(const LmiEnclosure& enc, const StateMetric& M, const ConReachSettings& s,
                   const MetricSdpSettings& sdp,
                   const std::function<double(const MetricSolution&)>& size_of, const double* c_prev,
                   const ReachStep& st) {
  try {
    return choose_metric(enc, M, s, sdp, size_of, c_prev);
  } catch (const VerificationFailure& e) {
    std::ostringstream os;
    os << "reach: step " << st.index << " on [" << st.t0 << ", " << st.t1 << "] s cannot be proved: "
       << e.what();
    throw VerificationFailure(os.str());
  }
}

/// The sub-step bisection of the step's tubes (tube.hpp).
TubeRefinement refinement(const RunFrame& f, const StepGrid& grid) {
  return {grid.h, f.s.max_bisections};
}

/// The step's metric (docs/reach.md, "Rate selection"), over U_i; for a loop whose LMI depends on
/// R with the product metric, U_i is redone once when the chosen Q falls below the floor.
StepChoice choose_step_metric(const RunFrame& f, const ReachStep& st, const StepStart& start,
                              const StepGrid& grid, const StateMetric& M, double r, const double* c_prev) {
  const ConReachSettings& s = f.s;
  const bool recover = f.coupled && st.index == 0;
  auto radius_for = [&](const MetricSolution& sol) { return recover ? recovered_radius(f, sol) : r; };
  // Product metric: the ball at t_{i+1}. Coupled metric: the ball at T if the rate held for
  // the rest of the horizon, because the metric can only shrink afterwards (M_{i+1} ⪯ M_i):
  // a metric that buys a lower rate pays for it once, and the rate pays back on every step.
  const double lookahead = f.coupled ? s.horizon - st.t0 : grid.dt;
  auto size_of = [&](const MetricSolution& sol) {
    return enclosure_radius({sol.Q, sol.S, sol.P}, radius_for(sol) * std::exp(sol.c * lookahead));
  };
  MetricSdpSettings sdp = s.sdp;
  sdp.coupled = f.coupled;
  sdp.rigorous = s.rigour == Rigour::rigorous;
  sdp.sdp.warm_start = f.warm;
  double q_floor = (f.att_dep && !f.coupled) ? s.attitude_floor_ratio * lambda_min(M.Q) : s.sdp.q_floor;
  StepChoice out;
  for (int pass = 0; pass < 2; ++pass) {
    const Deviation z_lmi = lmi_deviation(f, st.index, start.z_state, start.ball, r, q_floor);
    out.lmi_tube = (z_lmi == start.z_state)
                       ? start.state_tube
                       : propagate_tube(f.loop, start.points, z_lmi, NominalErrorTerm::bounded,
                                        refinement(f, grid));
    const LmiEnclosure enc = f.loop.lmi_enclosure(out.lmi_tube.attitude_hull, out.lmi_tube.omega_hull);
    sdp.q_floor = q_floor;
    out.choice = choose_step(enc, M, s, sdp, size_of, c_prev, st);
    out.lmi_exact = enc.exact;
    out.lmi_rho = enc.rho;
    // λ_min(Q) ≥ q_floor must hold for the floats: the proved lower bound decides.
    const double lq = proved_schur_lower({out.choice.sol.Q, Mat3::Zero(), out.choice.sol.P}, StateBlock::attitude);
    if (f.coupled || !f.att_dep || lq >= q_floor) break;
    if (pass == 1) throw NumericalError("ConReach: attitude enclosure of the metric ball is inconsistent");
    q_floor = lq * (1.0 - 1e-9);  // fallback metric below the floor: redo U_i with its λ_min
  }
  return out;
}

/// U_i and the chosen (c, Q, S, P) into the step.
void record_choice(ReachStep& st, const StepChoice& chosen) {
  const Choice& ch = chosen.choice;
  st.lmi_exact = chosen.lmi_exact;
  st.lmi_rho = chosen.lmi_rho;
  st.omega_box = chosen.lmi_tube.omega_hull;
  st.attitude_box = chosen.lmi_tube.attitude_hull;
  st.c_identity = ch.c_identity;
  st.c = ch.sol.c;
  st.Q = ch.sol.Q;
  st.S = ch.sol.S;
  st.P = ch.sol.P;
  st.fallback = ch.fallback;
  st.proved_rigorously = ch.sol.proved;
  st.sdp_solves = ch.solves;
  st.trials = ch.trials;
}

/// The ball at t_{i+1}: r_{i+1} = r_i e^{c Δt} + the nominal's error over the step in the new
/// metric. The ball's centre is the computed nominal point; the exact trajectory from the previous
/// centre ends within d_I ≤ e_R, ‖Δω‖ ≤ e_ω of it (tube.hpp), so in M within
/// metric_cover_radius(M, e_R, e_ω) (docs/reach.md, "Nominal error bound").
/// Every radius is proved for the floats (proved_radii.hpp); the growth uses the exact length of
/// [t_i, t_{i+1}] (the floats t0, t1), bounded on the side that makes e^{cΔt} larger.
void close_step(ReachStep& st, const Deviation& e, double r, double t0, double t1, const NominalPoint& end) {
  st.nominal_error_R = e.e_R;
  st.nominal_error_omega = e.e_omega_b;
  st.numerical_allowance = proved_cover_radius(st.metric(), e.e_R, e.e_omega_b);
  const double dt = st.c >= 0.0 ? Interval::up(t1 - t0) : Interval::down(t1 - t0);
  st.r = proved_ball_growth(r, st.c, dt, st.numerical_allowance);
  st.R = end.R;
  st.omega = end.omega;
  st.attitude_radius = proved_projection_radius(st.metric(), st.r, StateBlock::attitude);
  st.omega_half_widths = proved_omega_half_widths(st.metric(), st.r);
  if (!std::isfinite(st.r) || !st.Q.allFinite() || !st.P.allFinite() || !st.S.allFinite()) {
    std::ostringstream os;
    os << "ConReach: non-finite ball at t = " << st.t1 << " s";
    throw NumericalError(os.str());
  }
}

/// The nominal at the grid's times from the step's first point (simulate_from: bit for bit the
/// continuous simulation); NumericalError when it is not finite.
std::vector<NominalPoint> step_nominal(const ClosedLoop& loop, const NominalPoint& from, const StepGrid& grid) {
  std::vector<NominalPoint> pts(grid.times.size());
  try {
    simulate_from(loop, from.t, from.R, from.omega, grid.times, grid.h,
                  [&](std::size_t k, const Mat3& R, const Vec3& w) { pts[k] = {grid.times[k], R, w}; });
  } catch (const NumericalError& e) {
    std::ostringstream os;
    os << "ConReach: the nominal from t = " << from.t << " s (RKMK4 step " << grid.h << " s): " << e.what();
    throw NumericalError(os.str());
  }
  pts.front() = from;
  for (const auto& p : pts) {
    if (!p.R.allFinite() || !p.omega.allFinite()) throw NumericalError("ConReach: nominal trajectory is not finite");
  }
  return pts;
}

/// What a step computed, kept only when the step succeeds.
struct StepAttempt {
  ReachStep st;
  Deviation carried;                 ///< the state tube's end
  std::vector<NominalPoint> points;  ///< the state tube's nominal points
  int bisections{0};
  bool recovered{false};             ///< coupled step 0: the initial ball re-expressed
  double r0{0.0};
};

/// Step i of Algorithm 1 on `grid` from the ball B_M(x_i, r) centred at `from`: the state tube,
/// the metric over U_i, the ball at t_{i+1}. Throws EnclosureDiverges / VerificationFailure when
/// the interval cannot be carried.
StepAttempt reach_step(const RunFrame& f, int i, const StepGrid& grid, const NominalPoint& from,
                       const StateMetric& M, double r, const Deviation& carried, const double* c_prev) {
  StepAttempt out;
  ReachStep& st = out.st;
  st.index = i;
  st.t0 = grid.times.front();
  st.t1 = grid.times.back();
  StepStart start{step_nominal(f.loop, from, grid), ball_deviation(M, r), Deviation{}, TubeResult{}};
  start.z_state = carried.min(start.ball);
  start.state_tube = propagate_tube(f.loop, start.points, start.z_state, NominalErrorTerm::bounded,
                                    refinement(f, grid));
  out.carried = start.state_tube.end;
  out.points = start.state_tube.points;
  out.bisections = start.state_tube.bisections;
  st.state_tube = start.state_tube.segments;

  const StepChoice chosen = choose_step_metric(f, st, start, grid, M, r, c_prev);
  record_choice(st, chosen);
  // Coupled metric, step 0: the initial ball is re-expressed in the new metric M_1 itself,
  // B_{M_1}(x_0, r_0'), joined to the centre by the straight curves (R0 exp(sŵ), ω0 + sΔω)
  // inside the initial set (docs/reach.md, "Coupled metrics"): U_0 is the flow of the initial
  // set and M_1 ⪯ M_0 is only a normalisation.
  if (f.coupled && i == 0) {
    r = recovered_radius(f, chosen.choice.sol);
    out.recovered = true;
    out.r0 = r;
  }
  close_step(st, start.state_tube.nominal_error, r, grid.times.front(), grid.times.back(), out.points.back());
  return out;
}

/// The fixed grid of step i of N: t_i = i T/N, sub-steps t_i + j (T/N)/m, the last step ends at T.
StepGrid fixed_grid(const ConReachSettings& s, int i) {
  const int N = s.steps;
  const int m = s.substeps;
  const double dt = s.horizon / N;
  StepGrid g;
  for (int j = 0; j < m; ++j) g.times.push_back(i * dt + j * dt / m);
  g.times.push_back(i + 1 == N ? s.horizon : (i + 1) * dt);
  g.dt = dt;
  g.h = s.integrator_step;
  return g;
}

/// An adaptive step's grid on [t0, t0 + dt]: m equal sub-steps; the nominal's RKMK4 step is the
/// user's integrator_step, or 0.02/λ, at most one sub-step.
StepGrid adaptive_grid(const ConReachSettings& s, double t0, double dt, double rate_scale) {
  const int m = s.substeps;
  const double t1 = t0 + dt;
  StepGrid g;
  for (int j = 0; j < m; ++j) g.times.push_back(t0 + j * dt / m);
  g.times.push_back(t1);
  g.dt = t1 - t0;
  const double h = s.integrator_step > 0.0 ? s.integrator_step : 0.02 / rate_scale;
  g.h = std::min(h, dt / m);
  return g;
}

/// Commits a successful step into the result.
void commit_step(StepAttempt&& at, ReachResult& res, StateMetric& M, double& r, Deviation& carried) {
  res.sdp_solves += at.st.sdp_solves;
  res.bisections += at.bisections;
  if (at.recovered) {
    res.r0 = at.r0;
    res.Q0 = at.st.Q;
    res.S0 = at.st.S;
    res.P0 = at.st.P;
  }
  res.nominal.insert(res.nominal.end(), at.points.begin() + 1, at.points.end());
  carried = at.carried;
  M = at.st.metric();
  r = at.st.r;
  res.steps.push_back(std::move(at.st));
}

/// Marks the result as stopped at t with the reason.
void stop_at(ReachResult& res, double t, const std::string& why) {
  res.complete = false;
  res.stop_time = t;
  res.stop_reason = why;
}

}  // namespace

double loop_rate_scale(const ClosedLoop& loop, const InitialSet& initial) {
  const AttitudeBall att{initial.R0, initial.attitude_radius};
  const Box3 box = Box3::around(initial.omega0, Vec3::Constant(initial.omega_radius));
  const double a = loop.A_enclosure(att, box).abs_max().norm();
  const double b = loop.B_enclosure(att, box).abs_max().norm();
  const double w = box.norm_max();
  const double lambda = std::max({std::sqrt(a), b, w});
  return std::isfinite(lambda) ? lambda : 0.0;
}

namespace {

/// The ball being carried and the result it is carried into.
struct Carry {
  ReachResult& res;
  StateMetric M;
  double r;
  Deviation carried;
};

/// Step i on `grid` from the carried ball: the step, or nothing and `failure` when the
/// interval cannot be carried (EnclosureDiverges, VerificationFailure).
std::optional<StepAttempt> attempt_step(const RunFrame& f, const Carry& cs, int i, const StepGrid& grid,
                                        std::string& failure) {
  const double c_prev = cs.res.steps.empty() ? 0.0 : cs.res.steps.back().c;
  try {
    return reach_step(f, i, grid, cs.res.nominal.back(), cs.M, cs.r, cs.carried,
                      cs.res.steps.empty() ? nullptr : &c_prev);
  } catch (const EnclosureDiverges& e) {
    failure = e.what();
  } catch (const VerificationFailure& e) {
    failure = e.what();
  }
  return std::nullopt;
}

/// True (and the result stopped) when the settings' step_check refuses the last step.
bool stopped_by_check(const RunFrame& f, ReachResult& res) {
  if (!f.s.step_check) return false;
  double t = res.steps.back().t0;
  const std::string why = f.s.step_check(res.steps.back(), t);
  if (why.empty()) return false;
  stop_at(res, t, why);
  return true;
}

/// The user's grid: N steps of T/N; the first interval that cannot be carried ends the run.
void run_fixed(const RunFrame& f, Carry& cs) {
  for (int i = 0; i < f.s.steps; ++i) {
    const StepGrid grid = fixed_grid(f.s, i);
    std::string failure;
    std::optional<StepAttempt> at = attempt_step(f, cs, i, grid, failure);
    if (!at) {
      stop_at(cs.res, grid.times.front(), failure);
      return;
    }
    commit_step(std::move(*at), cs.res, cs.M, cs.r, cs.carried);
    if (stopped_by_check(f, cs.res)) return;
  }
}

/// Adaptive steps (docs/reach.md, "Adaptive steps"): first step 0.3/λ within [T/400, T/10]; a
/// step that cannot be carried is redone at half length down to 1/64 of the first; the next step
/// halves when the ball grew by more than e^{0.3} over the step and grows by 1.25 (up to 4× the
/// first, T/4 at most) when it contracted.
void run_adaptive(const RunFrame& f, const InitialSet& initial, Carry& cs) {
  const double lambda = loop_rate_scale(f.loop, initial);
  const double T = f.s.horizon;
  const double dt0 = std::clamp(lambda > 0.0 ? 0.3 / lambda : T / 10.0, T / 400.0, T / 10.0);
  const double dt_min = dt0 / 64.0;
  const double dt_max = std::min(T / 4.0, 4.0 * dt0);
  double dt = dt0;
  double t = 0.0;
  for (int i = 0; T - t > 1e-12 * T;) {
    if (i >= f.s.max_adaptive_steps) {
      std::ostringstream os;
      os << "reach: the adaptive steps reached max_adaptive_steps = " << f.s.max_adaptive_steps
         << " at t = " << t << " s";
      stop_at(cs.res, t, os.str());
      return;
    }
    double len = std::min(dt, T - t);
    if (T - (t + len) < 0.25 * len) len = T - t;  // no sliver at the horizon
    const StepGrid grid = adaptive_grid(f.s, t, len, lambda > 0.0 ? lambda : 1.0 / T);
    std::string failure;
    std::optional<StepAttempt> at = attempt_step(f, cs, i, grid, failure);
    if (!at) {
      if (!(len > dt_min * (1.0 + 1e-9))) {
        stop_at(cs.res, t, failure);
        return;
      }
      dt = std::max(dt_min, 0.5 * len);
      ++cs.res.retries;
      continue;
    }
    const double growth = at->st.c * len;
    commit_step(std::move(*at), cs.res, cs.M, cs.r, cs.carried);
    if (stopped_by_check(f, cs.res)) return;
    t = cs.res.steps.back().t1;
    ++i;
    if (growth > 0.3) {
      dt = std::max(dt_min, 0.5 * len);
    } else if (growth < 0.0) {
      dt = std::min(dt_max, 1.25 * std::max(dt, len));
    }
  }
}

}  // namespace

ReachResult run_conreach(const ClosedLoop& loop, const InitialSet& initial,
                         const ConReachSettings& s) {
  const auto wall0 = std::chrono::steady_clock::now();
  check_settings(initial, s);
  ReachResult res;
  res.initial = initial;
  res.P0 = initial.P0;
  // The initial set B_I(R0, a) × B(ω0, b) in the product metric (I, P0): √(a² + λ_max(P0) b²), proved.
  res.r0 = proved_cover_radius({Mat3::Identity(), Mat3::Zero(), initial.P0}, initial.attitude_radius,
                               initial.omega_radius);
  res.nominal.push_back({0.0, initial.R0, initial.omega0});
  DenseSdpWorkspace warm;
  const RunFrame frame{loop, s, initial.attitude_radius, initial.omega_radius,
                       s.metric == MetricKind::coupled, loop.lmi_depends_on_attitude(), &warm};
  Carry cs{res, StateMetric{Mat3::Identity(), Mat3::Zero(), initial.P0}, res.r0,
           Deviation::of_balls(initial.attitude_radius, initial.omega_radius)};
  if (s.adaptive) {
    run_adaptive(frame, initial, cs);
  } else {
    run_fixed(frame, cs);
  }
  res.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  return res;
}

}  // namespace attiguard::reach
