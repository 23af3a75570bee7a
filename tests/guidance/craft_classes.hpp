#pragma once
/// The craft classes of issue 25 (docs/waypoint.md, "Craft classes"): electric-propulsion tugs,
/// large chemical craft and cold-gas CubeSats, with non-diagonal inertia, 1–4 legs, a drifting
/// and rotating start and a user's cruise speed; each written as a `waypoint` scenario in profile
/// "craft" with `simulation.duration` = `duration_factor` × the tool's own prediction
/// (sim::predict_waypoint_mission). Used by AnySpacecraft.CraftClasses* and, with 10⁴ crafts,
/// by scripts/waypoint_any_spacecraft.sh (its CLASS_RUNS argument).

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>
#include <string>

#include "any_spacecraft.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/read_waypoint.hpp"
#include "attiguard/sim/waypoint_prediction.hpp"

namespace attiguard::test::any_spacecraft {

/// The classes of craft (issue 25).
enum class CraftClass { electric_tug, large_chemical, cubesat };
inline constexpr int kCraftClassCount = 3;

inline const char* class_name(CraftClass c) {
  switch (c) {
    case CraftClass::electric_tug: return "electric_tug";
    case CraftClass::large_chemical: return "large_chemical";
    case CraftClass::cubesat: return "cubesat";
  }
  return "?";
}

/// The ranges a class is drawn from (log-uniform unless said otherwise).
struct ClassRanges {
  double mass_lo, mass_hi;        ///< [kg]
  double radius_lo, radius_hi;    ///< radius of gyration of the largest moment [m]
  double accel_lo, accel_hi;      ///< main thrust / mass [m/s²]
  double rct_lo, rct_hi;          ///< one RCT's thrust / main thrust
  double wheel_lo, wheel_hi;      ///< wheel torque [N·m]
  double hz_lo, hz_hi;            ///< control rate [Hz]
  double leg_lo, leg_hi;          ///< leg length [m]
};

inline ClassRanges class_ranges(CraftClass c) {
  switch (c) {
    case CraftClass::electric_tug:  // 0.5–20 t, 2e-4–5e-3 m/s^2
      return {500.0, 2e4, 0.8, 3.0, 2e-4, 5e-3, 0.05, 0.5, 0.1, 2.0, 1.0, 10.0, 20.0, 5e4};
    case CraftClass::large_chemical:  // 2–20 t, J up to ~1e6 kg m^2, wheels 0.3–8 N m
      return {2000.0, 2e4, 1.0, 7.0, 0.02, 0.3, 0.01, 0.1, 0.3, 8.0, 1.0, 10.0, 20.0, 5e4};
    case CraftClass::cubesat:  // 1–12 kg, cold gas
      return {1.0, 12.0, 0.05, 0.15, 2e-3, 0.05, 0.05, 0.5, 1e-4, 5e-3, 1.0, 10.0, 20.0, 5e3};
  }
  return {};
}

/// One random craft of class `cls`: the case of stream `seed`, index k (deterministic), with the
/// duration `duration_factor` × the prediction of its own scenario.
inline Case make_class_case(CraftClass cls, unsigned long long seed, int k, double duration_factor = 1.5) {
  std::mt19937_64 g(seed * 1000003ULL + static_cast<unsigned long long>(k) * 7919ULL +
                    static_cast<unsigned long long>(cls));
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const ClassRanges r = class_ranges(cls);
  const double mass = log_uniform(g, r.mass_lo, r.mass_hi);
  const double radius = log_uniform(g, r.radius_lo, r.radius_hi);
  // Principal moments: the largest m r², the others 0.3–1 of it (triangle inequality kept).
  std::vector<double> m{mass * radius * radius, 0.0, 0.0};
  m[1] = m[0] * (0.5 + 0.5 * u(g));
  m[2] = std::max(m[0] - m[1], 0.0) + (m[1] + m[0] - std::max(m[0] - m[1], 0.0)) * (0.1 + 0.8 * u(g));
  std::sort(m.begin(), m.end());
  m[2] = std::min(m[2], 0.98 * (m[0] + m[1]));
  const Eigen::Quaterniond qa(Eigen::Vector4d(unit(g).x(), unit(g).y(), unit(g).z(), u(g) - 0.5).normalized());
  const Eigen::Matrix3d Ra = qa.toRotationMatrix();
  Eigen::Matrix3d J = Ra * Eigen::Vector3d(m[0], m[1], m[2]).asDiagonal() * Ra.transpose();
  J = (0.5 * (J + J.transpose())).eval();
  const double a = log_uniform(g, r.accel_lo, r.accel_hi);
  const double T = a * mass;
  const double f = log_uniform(g, r.rct_lo, r.rct_hi) * T;
  const double tau_w = log_uniform(g, r.wheel_lo, r.wheel_hi);
  const double Ts = 1.0 / log_uniform(g, r.hz_lo, r.hz_hi);
  const double a_rct = f / mass;
  // Accuracies the RCT can meet (quantum a_rct T_s below δ_v with a factor 2–10).
  const double dv_acc = std::max(log_uniform(g, 1e-3, 0.05), a_rct * Ts * (2.0 + 8.0 * u(g)));
  const double dp_acc = log_uniform(g, 0.1, 2.0);
  const int n = 1 + static_cast<int>(u(g) * 4.0);
  std::vector<double> legs;
  for (int i = 0; i < n; ++i) legs.push_back(log_uniform(g, r.leg_lo, r.leg_hi));
  const double L_typ = *std::max_element(legs.begin(), legs.end());
  // The user's cruise speed: 0.3–1 of the bang-bang peak of the longest leg.
  const double V = std::sqrt(a * L_typ) * (0.3 + 0.7 * u(g));
  const Eigen::Vector3d v0 = unit(g) * (0.05 * V * u(g));  // drifting start
  const Eigen::Vector3d w0 = unit(g) * (0.2 * std::sqrt(tau_w / m[2]) * u(g));  // rotating start
  const Eigen::Quaterniond q0(Eigen::Vector4d(unit(g).x(), unit(g).y(), unit(g).z(), u(g) - 0.5).normalized());

  std::ostringstream head;
  head.precision(17);
  head << "kind = \"waypoint\"\nname = \"" << class_name(cls) << "_" << k << "\"\n[spacecraft]\nmass = " << mass
       << "\ninertia = [" << vec(J.row(0)) << ", " << vec(J.row(1)) << ", " << vec(J.row(2))
       << "]\nmain_thrust = " << T << "\nrct_thrust = " << f << "\nmax_wheel_torque = " << tau_w
       << "\n[initial]\nvelocity = " << vec(v0) << "\nomega_b = " << vec(w0)
       << "\nattitude = { quaternion = [" << q0.w() << ", " << q0.x() << ", " << q0.y() << ", " << q0.z()
       << "] }\n";
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  Eigen::Vector3d dir = unit(g);
  Case c;
  for (int i = 0; i < n; ++i) {
    if (i > 0) {  // turns of 0–180 deg between legs
      const Eigen::Vector3d side = dir.cross(unit(g)).normalized();
      const double turn = std::acos(1.0 - 2.0 * u(g));
      dir = (std::cos(turn) * dir + std::sin(turn) * side).normalized();
    }
    p += dir * legs[static_cast<std::size_t>(i)];
    head << "[[waypoints]]\nposition = " << vec(p) << "\n";
    // The user's estimate: a trapezoid at V (or a triangle) plus two half-turns at the wheel limit.
    double dv = 0.0, t = 0.0;
    ideal_leg(legs[static_cast<std::size_t>(i)], a, V, dv, t);
    c.ideal_time += t + 2.0 * 2.0 * std::sqrt(M_PI * m[2] / tau_w);
    c.ideal_delta_v += dv;
  }
  std::ostringstream guidance;
  guidance.precision(17);
  guidance << "[guidance]\ncruise_speed = " << V << "\narrival_radius = " << 0.05 * dp_acc
           << "\nposition_accuracy = " << dp_acc << "\nspeed_accuracy = " << dv_acc << "\n";
  auto simulation = [&](double duration) {
    std::ostringstream s;
    s.precision(17);
    s << "[simulation]\nduration = " << duration << "\ncontrol_period = " << Ts
      << "\noutput_interval = " << std::max(10.0, Ts) << "\nstep = " << Ts << "\n";
    return s.str();
  };
  // The prediction needs only the craft and the mission: predict with a placeholder duration.
  c.toml = head.str() + guidance.str() + simulation(1e6);
  try {
    const sim::WaypointScenario sc = scenario::parse_waypoint(scenario::parse_document(c.toml, "class.toml"));
    c.predicted_time = sim::predict_waypoint_mission(sc).time;
    c.toml = head.str() + guidance.str() + simulation(std::max(duration_factor * c.predicted_time, 10.0 * Ts));
  } catch (const InputError&) {
    // Refused up front: judge() reports the reason.
  }
  return c;
}

}  // namespace attiguard::test::any_spacecraft
