#include "attiguard/sim/pet_erg_loop.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "attiguard/dynamics/eigenaxis_slew.hpp"
#include "attiguard/sim/time_grid.hpp"

namespace attiguard::sim::pet_erg_loop {

using governor::GovernorMode;
using governor::GovernorOutput;
using lie::Vec3;

/// Sampling instants k·T_s in (0, duration), output instants, and schedule waypoints in
/// (0, duration), merged (instants closer than 1e-9·min(T_s, output_interval) are one stop).
std::vector<Stop> stop_plan(const PetErgScenario& sc) {
  std::vector<Stop> stops;
  for (double t : uniform_instants(sc.duration, sc.output_interval)) {
    stops.push_back({t, false, true});
  }
  if (sc.control_period > 0.0) {
    // The flight loop: the governor's own clock evaluates (5) at the control instants.
    for (long k = 1;; ++k) {
      const double t = static_cast<double>(k) * sc.control_period;
      if (t >= sc.duration - 1e-9 * sc.control_period) {
        break;
      }
      stops.push_back({t, false, false, true});
    }
  } else if (sc.params.mode != GovernorMode::none) {
    // (5) in mode pet; the saddle tie-break in modes pet and continuous (docs/pet-erg.md, section 4).
    for (long k = 1;; ++k) {
      const double t = static_cast<double>(k) * sc.params.Ts;
      if (t >= sc.duration - 1e-9 * sc.params.Ts) {
        break;
      }
      stops.push_back({t, true, false});
    }
  }
  for (int i = 0; i < sc.desired.size(); ++i) {
    const double t = sc.desired[i].t;
    if (t > 0.0 && t < sc.duration) {
      stops.push_back({t, false, false});
    }
  }
  std::stable_sort(stops.begin(), stops.end(), [](const Stop& a, const Stop& b) { return a.t < b.t; });
  const double merge = 1e-9 * std::min({sc.params.Ts, sc.output_interval,
                                        sc.control_period > 0.0 ? sc.control_period : sc.params.Ts});
  std::vector<Stop> merged;
  for (const Stop& s : stops) {
    if (!merged.empty() && s.t - merged.back().t <= merge) {
      Stop& m = merged.back();
      m.sample = m.sample || s.sample;
      m.output = m.output || s.output;
      m.control = m.control || s.control;
      // Keep the exact multiple k·T_s (or the duration) as the stop time.
      if (s.sample || s.control || (s.output && !m.sample && !m.control)) {
        m.t = s.t;
      }
      continue;
    }
    merged.push_back(s);
  }
  return merged;
}

/// The end of a run: distance left, active cones, the eigenaxis bang-bang time of the slew and
/// the outcome (docs/pet-erg.md, "Outcomes"), R_d_end = R_d(duration). r.convergence_time and
/// r.reference_motion are set.
void finish_outcome(const PetErgScenario& sc, const Mat3& R_g_end, const Mat3& R_d_end,
                    PetErgResult& r) {
  r.reference_distance_left = lie::distance(R_g_end, R_d_end);
  r.active_cones.clear();
  const std::vector<governor::ConeConstraint>& cones = r.design.cones;  // the field's bands
  for (std::size_t i = 0; i < cones.size(); ++i) {
    if (governor::cone_cosine(cones[i], R_g_end) < cones[i].zeta) {
      r.active_cones.push_back(static_cast<int>(i));
    }
  }
  r.slew_angle = lie::distance(sc.R0_ib, R_d_end);
  r.eigenaxis_bang_bang_time =
      dynamics::eigenaxis_bang_bang_time(sc.params.J, sc.R0_ib, R_d_end, sc.params.tau_max);
  const lie::Vec3 rotation_b = lie::log(sc.R0_ib.transpose() * R_d_end);
  if (!sc.wheels.empty() && rotation_b.norm() > 0.0) {
    // The wheels' own: the torque they apply unclipped along J k, within τ_max.
    const double tau = wheel_slabs(sc).torque_along(sc.params.J * rotation_b.normalized());
    r.wheel_bang_bang_time = dynamics::eigenaxis_bang_bang_time(sc.params.J, sc.R0_ib, R_d_end, tau);
  }
  OutcomeEvidence e;
  e.governed = sc.params.mode != GovernorMode::none;
  e.convergence_time = r.convergence_time;
  e.distance_left = r.reference_distance_left;
  e.distance_tolerance = std::acos(std::max(-1.0, 1.0 - sc.convergence_tolerance));
  e.last_half = r.reference_motion;
  r.outcome = classify_outcome(e);
}

/// The figures known before the run starts, with the governor's design.
PetErgResult initial_result(const PetErgScenario& sc, governor::GovernorDesign design,
                            const governor::AttitudeGovernor& gov) {
  PetErgResult r;
  r.design = std::move(design);
  r.gamma_d = gov.gamma_d();
  r.gamma_d_upper = gov.torque_threshold().upper_bound;
  r.gamma_d_loose = gov.gamma_d_loose();
  r.gamma_cap = gov.gamma_cap();
  r.gamma_g_initial = gov.gamma_g(sc.R_g0);
  r.gamma_initial = gov.gamma(sc.R_g0);
  r.V_initial = gov.level(sc.R0_ib, sc.omega0_b, sc.R_g0);
  r.min_pointing_margin = std::numeric_limits<double>::infinity();
  r.min_margin_per_cone.assign(sc.cones.size(), std::numeric_limits<double>::infinity());
  r.max_V_minus_Gamma = -std::numeric_limits<double>::infinity();
  r.reference_motion = ReferenceMotion(0.5 * sc.duration);
  return r;
}

/// A saddle tie-break started at t around cone `cone` (docs/pet-erg.md, section 4).
void note_tie_break(PetErgResult& r, double t, int cone) {
  if (r.saddle_tie_breaks++ == 0) r.first_tie_break_time = t;
  if (std::find(r.tie_break_cones.begin(), r.tie_break_cones.end(), cone) == r.tie_break_cones.end()) {
    r.tie_break_cones.push_back(cone);
  }
}

/// Folds one instant into the figures: `out` is the governor's view with the torque applied.
void record(const PetErgScenario& sc, PetErgResult& r, double t, const Mat3& R_d, const Mat3& R_ib,
            const GovernorOutput& out) {
  if (lie::phi(R_d.transpose() * R_ib) > sc.convergence_tolerance) {
    r.convergence_time = -1.0;
  } else if (r.convergence_time < 0.0) {
    r.convergence_time = t;
  }
  r.reference_motion.observe(t, out.R_g);
  r.max_torque_norm = std::max(r.max_torque_norm, out.tau_b.norm());
  r.max_V_minus_Gamma = std::max(r.max_V_minus_Gamma, out.W - out.gamma);
  for (int i = 0; i < out.cone_count; ++i) {
    const double m = out.margins[static_cast<std::size_t>(i)];
    auto& mi = r.min_margin_per_cone[static_cast<std::size_t>(i)];
    mi = std::min(mi, m);
    r.min_pointing_margin = std::min(r.min_pointing_margin, m);
    if (m < 0.0 && r.first_pointing_violation_time < 0.0) {
      r.first_pointing_violation_time = t;
    }
  }
}

/// The end of either loop: final errors, outcome and the integrator's counters.
void finish(const PetErgScenario& sc, const PetErgState& y, const integrate::IntegrationStats& stats,
            PetErgResult& r) {
  const Mat3 R_d_end = sc.desired.at(sc.duration);
  const Mat3 R_g_end = sc.params.mode == GovernorMode::none ? R_d_end : y.R[1];
  r.final_attitude_error = std::max(0.0, lie::phi(R_d_end.transpose() * y.R[0]));
  r.final_reference_error = std::max(0.0, lie::phi(R_d_end.transpose() * R_g_end));
  r.final_omega_norm = y.x.norm();
  finish_outcome(sc, R_g_end, R_d_end, r);
  r.steps = stats.accepted_steps;
  r.rejected_steps = stats.rejected_steps;
  r.evaluations = stats.evaluations;
}

std::vector<double> stop_times(const std::vector<Stop>& plan) {
  std::vector<double> times;
  times.reserve(plan.size());
  for (const Stop& s : plan) {
    times.push_back(s.t);
  }
  return times;
}

/// The state of either loop at t = 0: (R_0, R_g(0), ω_0) of the scenario's [initial].
PetErgState pet_erg_initial_state(const PetErgScenario& sc) {
  PetErgState y;
  y.R[0] = sc.R0_ib;
  y.R[1] = sc.R_g0;
  y.x = sc.omega0_b;
  return y;
}

/// The wheels' figures of a flight-loop run (docs/pet-erg.md, section 12): the demand and
/// momentum ratios, the momenta at the end, and Γ_d's upper bracket of the wheel polytope.
void finish_wheels(const PetErgScenario& sc, const HeldActuation& actuation, PetErgResult& r) {
  r.max_wheel_torque_ratio = actuation.max_wheel_torque_ratio();
  r.max_wheel_momentum_ratio = actuation.max_wheel_momentum_ratio();
  if (!actuation.has_wheels()) return;
  const dynamics::WheelVector h = actuation.momenta(sc.duration);
  r.final_wheel_momentum.assign(h.begin(), h.begin() + actuation.wheels().count());
  r.gamma_d_upper = std::min(r.gamma_d_upper, r.design.wheels.gamma_d_upper);
}

}  // namespace attiguard::sim::pet_erg_loop
