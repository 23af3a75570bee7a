#pragma once
/// The "any spacecraft" property of issue 13 (docs/waypoint.md, "Tuning"): random crafts (mass
/// 10–5000 kg, principal moments drawn independently log-uniform in 1–10⁴ kg·m² — ratios up to
/// ≈ 10⁴, the largest clipped below the sum of the other two — about random principal axes,
/// thrust-to-mass 0.001–1 m/s², RCT
/// authority 0.01–0.5 of the main thrust, control 1–50 Hz), random accuracies, random waypoint
/// lists of 1–5 (collinear, reversing, zero-length and behind-the-craft legs) and random initial
/// velocity, each written as a `waypoint` scenario file in profile "craft" (every guidance key
/// derived) and judged: rejected up front by `check` (with its reason), completed, or not. Used by
/// AnySpacecraft.* with a few hundred crafts and by scripts/waypoint_any_spacecraft.sh with 10⁴.
/// Measured (seed 13, inertia-shaped attitude PID, before the RCT braking curve of issue 25): 10⁴ crafts, 2367 rejected (all at
/// guidance.speed_accuracy), 7633 accepted, 7632 completed (99.99 %), 1 time-out (case 8249: the
/// duration budget below is short for its RCT-flown legs), 0 NaN/divergence; median Δv/ideal
/// 0.641, time/ideal 2.813. 300 crafts (the suite): 220 accepted, 220 completed.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "attiguard/core/errors.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/read_waypoint.hpp"
#include "attiguard/sim/waypoint_run.hpp"
#include "attiguard/sim/waypoint_prediction.hpp"

namespace attiguard::test::any_spacecraft {

/// One random craft and mission as scenario text, with what the ideal manoeuvre would cost.
struct Case {
  std::string toml;
  double ideal_delta_v{0.0};  ///< Σ legs of rest-to-rest bang-coast-bang at V_d, + ‖v0‖ [m/s]
  double ideal_time{0.0};     ///< Σ legs of its duration [s] (craft classes: plus two wheel-limited half-turns)
  double predicted_time{0.0};  ///< sim::predict_waypoint_mission's (craft classes only) [s]
};

inline double log_uniform(std::mt19937_64& g, double lo, double hi) {
  std::uniform_real_distribution<double> u(std::log(lo), std::log(hi));
  return std::exp(u(g));
}

inline std::string vec(const Eigen::Vector3d& v) {
  std::ostringstream os;
  os.precision(17);
  os << "[" << v(0) << ", " << v(1) << ", " << v(2) << "]";
  return os.str();
}

inline Eigen::Vector3d unit(std::mt19937_64& g) {
  std::normal_distribution<double> n(0.0, 1.0);
  Eigen::Vector3d v(n(g), n(g), n(g));
  return v.normalized();
}

/// Rest-to-rest bang-coast-bang over `leg` m with acceleration a and speed limit V: Δv and time.
inline void ideal_leg(double leg, double a, double V, double& dv, double& t) {
  if (!(leg > 0.0)) return;
  const double v_peak = std::min(V, std::sqrt(a * leg));
  dv += 2.0 * v_peak;
  t += 2.0 * v_peak / a + (leg - v_peak * v_peak / a) / v_peak;
}

/// The k-th random case of the stream seeded with `seed` (deterministic).
inline Case make_case(unsigned long long seed, int k) {
  std::mt19937_64 g(seed * 1000003ULL + static_cast<unsigned long long>(k));
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double mass = log_uniform(g, 10.0, 5000.0);
  // Principal moments drawn independently, log-uniform in 1–1e4 kg m^2, sorted, the largest
  // clipped below m0 + m1 (triangle inequality), random principal axes.
  std::vector<double> m{log_uniform(g, 1.0, 1e4), log_uniform(g, 1.0, 1e4), log_uniform(g, 1.0, 1e4)};
  std::sort(m.begin(), m.end());
  m[2] = std::max(m[1], std::min(m[2], 0.98 * (m[0] + m[1])));  // m1 <= m2 < m0 + m1
  const Eigen::Quaterniond qa(Eigen::Vector4d(unit(g).x(), unit(g).y(), unit(g).z(), u(g) - 0.5).normalized());
  const Eigen::Matrix3d Ra = qa.toRotationMatrix();
  Eigen::Matrix3d J = Ra * Eigen::Vector3d(m[0], m[1], m[2]).asDiagonal() * Ra.transpose();
  J = (0.5 * (J + J.transpose())).eval();  // exactly symmetric
  const double a = log_uniform(g, 1e-3, 1.0);  // thrust-to-mass [m/s^2]
  const double T = a * mass;
  const double f = (0.01 + 0.49 * u(g)) * T;  // RCT authority
  const double hz = log_uniform(g, 1.0, 50.0);
  const double Ts = 1.0 / hz;
  const double dv_acc = log_uniform(g, 1e-3, 0.05);
  const double dp_acc = log_uniform(g, 0.05, 2.0);
  // Legs of 20–150 s of bang-bang flight at this acceleration; V_d 0.3–1.5 of a typical peak.
  const double t_leg = log_uniform(g, 20.0, 150.0);
  const double L = a * t_leg * t_leg / 4.0;
  const double V = std::sqrt(a * L) * (0.3 + 1.2 * u(g));
  const Eigen::Vector3d v0 = u(g) < 0.2 ? Eigen::Vector3d::Zero() : Eigen::Vector3d(unit(g) * V * 1.2 * u(g));
  const Eigen::Quaterniond q0(Eigen::Vector4d(unit(g).x(), unit(g).y(), unit(g).z(), u(g) - 0.5).normalized());

  Case c;
  std::ostringstream os;
  os.precision(17);
  os << "kind = \"waypoint\"\nname = \"any_spacecraft_" << k << "\"\n[spacecraft]\nmass = " << mass
     << "\ninertia = [" << vec(J.row(0)) << ", " << vec(J.row(1)) << ", " << vec(J.row(2))
     << "]\nmain_thrust = " << T << "\nrct_thrust = " << f << "\n[initial]\nvelocity = " << vec(v0)
     << "\nattitude = { quaternion = [" << q0.w() << ", " << q0.x() << ", " << q0.y() << ", " << q0.z()
     << "] }\n";
  const int n = 1 + static_cast<int>(u(g) * 5.0);
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  Eigen::Vector3d dir = unit(g);
  double ideal_dv = v0.norm();
  double ideal_t = 0.0;
  for (int i = 0; i < n; ++i) {
    const double r = u(g);
    Eigen::Vector3d next;
    if (r < 0.15) {
      next = p;  // zero-length leg (the start point itself for the first waypoint)
    } else if (r < 0.35) {
      next = p + dir * L * (0.3 + u(g));  // collinear with the previous leg
    } else if (r < 0.55) {
      dir = -dir;  // reversal: back along the previous leg (behind the craft for the first)
      if (i == 0 && v0.norm() > 0.0) dir = -v0.normalized();
      next = p + dir * L * (0.3 + u(g));
    } else {
      dir = unit(g);
      next = p + dir * L * (0.3 + u(g));
    }
    ideal_leg((next - p).norm(), a, V, ideal_dv, ideal_t);
    p = next;
    os << "[[waypoints]]\nposition = " << vec(p) << "\n";
  }
  // Generous: 4 × the ideal plus the slews and fine control a slow craft needs.
  const double duration = 4.0 * ideal_t + 400.0 * (n + 1) + 2000.0;
  os << "[guidance]\ncruise_speed = " << V << "\narrival_radius = " << 0.05 * dp_acc
     << "\nposition_accuracy = " << dp_acc << "\nspeed_accuracy = " << dv_acc
     << "\n[simulation]\nduration = " << duration << "\ncontrol_period = " << Ts
     << "\noutput_interval = " << std::max(1.0, Ts) << "\nstep = " << Ts << "\n";
  c.toml = os.str();
  c.ideal_delta_v = ideal_dv;
  c.ideal_time = ideal_t;
  return c;
}

/// What became of one case.
struct Verdict {
  enum Kind { rejected, completed, incomplete, failed } kind{failed};
  std::string reason;  ///< the check's message, the outcome reason, or the numerical error
  double delta_v_ratio{0.0};
  double time_ratio{0.0};
  double predicted_ratio{0.0};  ///< mission time over sim::predict_waypoint_mission's (completed runs)
  double fine_fraction{0.0};    ///< time in mode fine over the mission time (completed runs)
  /// The part of fine_fraction in legs flown by the RCT alone (a leg started in fine: the
  /// sequencer's choice for legs within half the re-plan distance) (completed runs)
  double rct_leg_fraction{0.0};
  /// Time in mode fine by how it was entered ("decelerate->fine: closest_approach", an
  /// RCT-only leg "fine->fine: accuracy_met", …) [s] (completed runs; docs/waypoint.md, "Craft classes").
  std::map<std::string, double> fine_time_by_entry;
  double total_time{0.0};       ///< the mission time [s] (completed runs)
  /// Time in mode rct_transfer over the mission time (completed runs; docs/waypoint.md, "The
  /// RCT-only legs")
  double transfer_fraction{0.0};
  /// Σ time of the legs flown by the RCT alone (started in fine or rct_transfer), from the
  /// leg's start to its waypoint's accuracy [s] (completed runs)
  double rct_leg_time{0.0};
  int rct_legs{0};  ///< how many such legs (completed runs)
};

/// Time per mode and the RCT-only legs of a run, from its transitions (docs/waypoint.md, "The
/// RCT-only legs"): a leg is RCT-only when it starts (t = 0 or accuracy_met of the previous
/// waypoint) in fine or rct_transfer.
struct ModeTimes {
  double fine{0.0};
  double transfer{0.0};
  double rct_leg_time{0.0};
  int rct_legs{0};
};
inline ModeTimes mode_times(const sim::WaypointSimResult& res) {
  ModeTimes m;
  const auto rct_mode = [](guidance::Mode mode) {
    return mode == guidance::Mode::fine || mode == guidance::Mode::rct_transfer;
  };
  guidance::Mode mode = res.transitions.empty() ? guidance::Mode::done : res.transitions.front().from;
  double t0 = 0.0, leg_start = 0.0;
  bool rct_leg = rct_mode(mode);
  for (std::size_t i = 0; i <= res.transitions.size(); ++i) {
    const double t = i < res.transitions.size() ? res.transitions[i].t : res.total_time;
    if (mode == guidance::Mode::fine) m.fine += t - t0;
    if (mode == guidance::Mode::rct_transfer) m.transfer += t - t0;
    if (i == res.transitions.size()) break;
    const auto& tr = res.transitions[i];
    if (tr.reason == guidance::TransitionReason::accuracy_met) {
      if (rct_leg) {
        m.rct_leg_time += t - leg_start;
        ++m.rct_legs;
      }
      leg_start = t;
      rct_leg = rct_mode(tr.to);
    }
    mode = tr.to;
    t0 = t;
  }
  return m;
}

/// ATTIGUARD_RCT_TRANSFER=0 flies the RCT-only legs by fine control alone (guidance.rct_transfer
/// false), for the before/after comparison on the same crafts (docs/waypoint.md, "The RCT-only legs").
inline void apply_rct_transfer_override(sim::WaypointScenario& sc) {
  const char* v = std::getenv("ATTIGUARD_RCT_TRANSFER");
  if (v != nullptr) sc.mission.rct_transfer = std::string(v) != "0";
}

inline Verdict judge(const Case& c) {
  Verdict v;
  sim::WaypointScenario sc;
  try {
    sc = scenario::parse_waypoint(scenario::parse_document(c.toml, "any_spacecraft.toml"));
  } catch (const InputError& e) {
    v.kind = Verdict::rejected;
    v.reason = e.what();
    return v;
  }
  apply_rct_transfer_override(sc);
  try {
    const sim::WaypointSimResult res = sim::simulate_waypoint(sc);
    const sim::WaypointOutcome out = sim::waypoint_outcome(sc, res);
    if (!res.finite) {
      v.kind = Verdict::failed;
      v.reason = "non-finite state or command";
      return v;
    }
    v.kind = out.completed ? Verdict::completed : Verdict::incomplete;
    v.reason = out.reason;
    double dv = 0.0;
    for (const sim::WaypointResult& w : res.waypoints) dv += w.delta_v();
    v.delta_v_ratio = c.ideal_delta_v > 0.0 ? dv / c.ideal_delta_v : 0.0;
    v.time_ratio = c.ideal_time > 0.0 ? res.total_time / c.ideal_time : 0.0;
    const double predicted = sim::predict_waypoint_mission(sc).time;
    double t_fine = 0.0;
    if (!res.transitions.empty() && res.transitions.front().from == guidance::Mode::fine) {
      // The first leg started in fine control (an RCT-only leg): no transition entered it.
      t_fine += res.transitions.front().t;
      v.fine_time_by_entry["start->fine: rct_leg"] += res.transitions.front().t;
    }
    for (std::size_t i = 0; i < res.transitions.size(); ++i) {
      if (res.transitions[i].to != guidance::Mode::fine) continue;
      const double end = i + 1 < res.transitions.size() ? res.transitions[i + 1].t : res.total_time;
      t_fine += end - res.transitions[i].t;
      v.fine_time_by_entry[std::string(guidance::mode_name(res.transitions[i].from)) + "->fine: " +
                           guidance::reason_name(res.transitions[i].reason)] += end - res.transitions[i].t;
    }
    v.total_time = res.total_time;
    v.fine_fraction = res.total_time > 0.0 ? t_fine / res.total_time : 0.0;
    double t_rct_legs = 0.0;
    for (const auto& [entry, t] : v.fine_time_by_entry) {
      if (entry.rfind("start->fine", 0) == 0 || entry.rfind("fine->fine", 0) == 0 ||
          entry.rfind("rct_transfer->fine", 0) == 0) {
        t_rct_legs += t;
      }
    }
    const ModeTimes mt = mode_times(res);
    v.transfer_fraction = res.total_time > 0.0 ? mt.transfer / res.total_time : 0.0;
    v.rct_leg_time = mt.rct_leg_time;
    v.rct_legs = mt.rct_legs;
    v.rct_leg_fraction = res.total_time > 0.0 ? t_rct_legs / res.total_time : 0.0;
    v.predicted_ratio = predicted > 0.0 ? res.total_time / predicted : 0.0;
  } catch (const NumericalError& e) {
    v.kind = Verdict::failed;
    v.reason = e.what();
  }
  return v;
}

}  // namespace attiguard::test::any_spacecraft
