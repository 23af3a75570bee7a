/// @file mission_slews.cpp
/// The planned slews of kind `mission` (docs/mission.md, "Planned slews").

#include "attiguard/sim/mission_slews.hpp"

#include <algorithm>
#include <string>
#include <utility>

#include "attiguard/control/so3_tracking.hpp"
#include "attiguard/core/errors.hpp"
#include "attiguard/core/four_digits.hpp"
#include "attiguard/governor/default_gains.hpp"
#include "attiguard/lie/quaternion.hpp"
#include "attiguard/sim/planned_run.hpp"

namespace attiguard::sim {

using lie::Mat3;
using lie::Vec3;

PetErgScenario mission_slew_scenario(const MissionScenario& sc, const Mat3& R_ib, const Vec3& omega_b,
                                     const Mat3& R_d) {
  PetErgScenario ps;
  ps.name = sc.waypoint.name;
  ps.params = sc.params;
  ps.params.mode = governor::GovernorMode::planned;
  ps.cones = sc.cones;
  ps.R0_ib = R_ib;
  ps.R_g0 = R_ib;
  ps.omega0_b = omega_b;
  ps.desired = governor::ReferenceSchedule(R_d);
  ps.control_period = sc.waypoint.control_period;
  const double clamp = sc.waypoint.max_wheel_torque;
  if (clamp > 0.0) {
    // The plant's per-axis clamp (dynamics::SpacecraftPlant) as three orthogonal wheels: the
    // torque of every direction is their inscribed radius, the clamp itself. Their momentum is
    // not modelled by the mission's plant; the planner reads only the torque.
    for (int i = 0; i < 3; ++i) {
      ps.wheels.push_back(dynamics::ReactionWheel{Vec3::Unit(i), clamp, 1.0, 0.0});
    }
  }
  ps.duration = sc.waypoint.duration;
  ps.output_interval = sc.waypoint.output_interval;
  ps.integrator = sc.waypoint.integrator;
  return ps;
}

MissionSlews::MissionSlews(const MissionScenario& sc)
    : sc_(sc),
      gains_{sc.params.gains.kp, sc.params.gains.kd},
      heading_(sc.waypoint.R0_ib) {
  // The bound the planned governor keeps (planned_setup's τ_max − 0: min(τ_max, the clamp)).
  tau_bound_ = governor::effective_torque(
      craft_scales(mission_slew_scenario(sc, sc.waypoint.R0_ib, Vec3::Zero(), sc.waypoint.R0_ib)));
  slews_.reserve(16);
  out_.cone_count = static_cast<int>(sc.cones.size());
}

void MissionSlews::start_slew(double t, const Mat3& R, const Vec3& omega, const Mat3& R_d,
                              const guidance::MissionCommand& cmd) {
  if (!slews_.empty()) slews_.back().end_time = t;
  MissionSlew& s = slews_.emplace_back();
  s.index = static_cast<int>(slews_.size()) - 1;
  s.start_time = t;
  s.waypoint = cmd.waypoint;
  s.mode = cmd.mode;
  s.angle = lie::distance(R, R_d);
  heading_ = R_d;
  target_ = R_d;
  gov_.reset();
  flying_ = false;
  try {
    const PlannedSetup setup = planned_setup(mission_slew_scenario(sc_, R, omega, R_d));
    s.figures = setup.figures;
    gov_.emplace(setup.planned.plan, sc_.cones, setup.params);
    gov_->reset(t);
    s.planned = true;
    flying_ = true;
  } catch (const PlannedSetupRefusal& e) {
    s.not_planned_reason = e.message();  // shorter than ten control periods: tracked
  } catch (const VerificationFailure& e) {
    // No admissible path (exit 4, as `attiguard plan`): named with the slew it ends.
    throw VerificationFailure("mission: the " + std::string(guidance::mode_name(cmd.mode)) +
                              " slew at t = " + four_digits(t) + " s (waypoint " +
                              std::to_string(cmd.waypoint) + ") cannot be planned: " + e.what());
  }
}

void MissionSlews::fly_plan(double t, const Mat3& R, const Vec3& omega) {
  const governor::PlannedOutput& p = gov_->step(t, R, omega);
  PlannedFigures& f = slews_.back().figures;
  const double T_p = gov_->progress().plan().duration();
  if (p.sampled) {
    ++f.samples;
    if (!p.choice.admissible) ++f.inadmissible_samples;
    if (p.choice.rule == governor::RateRule::brake) ++f.brakes;
    if (p.sigma < T_p) {
      f.min_rate = std::min(f.min_rate, p.choice.rate);
      if (p.choice.rate == 0.0 && p.choice.accel == 0.0) f.time_held += sc_.waypoint.control_period;
    }
    f.max_torque_bound_ratio = std::max(f.max_torque_bound_ratio, p.choice.torque_bound / f.tau_max);
  }
  f.max_demand_ratio = std::max(f.max_demand_ratio, p.demand_ratio);
  if (p.demand_ratio > 1.0) ++f.saturated_commands;
  f.final_progress = p.sigma;
  f.final_rate = p.rate;
  out_.tau_b = p.tau_b;
  out_.R_g = p.reference.R_ib;
  out_.V = out_.W = p.V;
  out_.trigger = p.choice.admissible;
  state_ = MissionSlewState{slews_.back().index, p.sigma, p.rate};
  if (p.sigma >= T_p) {
    f.progress_end_time = t - slews_.back().start_time;
    flying_ = false;  // the plan is flown: from the next sample the loop tracks R_d
  }
}

void MissionSlews::track(const Mat3& R, const Vec3& omega, const Mat3& R_d, const Vec3& omega_d) {
  const control::TrackingReference ref{R_d, omega_d, Vec3::Zero()};
  const Vec3 law = control::tracking_torque(sc_.params.J, R, omega, ref, gains_);
  const double norm = law.norm();
  // The planned mode's saturation (docs/pet-erg.md, section 16.2, "Saturation").
  out_.tau_b = norm > tau_bound_ ? Vec3(law * ((1.0 - 4e-16) * tau_bound_ / norm)) : law;
  out_.R_g = R_d;
  out_.V = out_.W = control::tracking_lyapunov(sc_.params.J, R, omega, ref, gains_);
  out_.trigger = true;
  state_ = MissionSlewState{-1, 0.0, 0.0};
  heading_ = R_d;
}

const governor::GovernorOutput& MissionSlews::step(double t, const dynamics::SpacecraftState& y,
                                                   const guidance::MissionCommand& cmd) {
  const Mat3& R = y.R[0];
  const Vec3 omega = dynamics::omega_b_of(y);
  const Mat3 R_d = lie::quat_to_rotation(cmd.q_id);
  // Set-up at the slew's start only (planning allocates); the steps between allocate nothing.
  if (lie::distance(heading_, R_d) > sc_.align_tolerance) start_slew(t, R, omega, R_d, cmd);
  if (flying_) {
    fly_plan(t, R, omega);
  } else {
    track(R, omega, R_d, cmd.omega_d_d);
  }
  if (!slews_.empty()) {
    MissionSlew& s = slews_.back();
    const Mat3& R_T = s.planned ? target_ : heading_;
    if (s.convergence_time < 0.0 && lie::phi(R_T.transpose() * R) <= kMissionSlewConvergence) {
      s.convergence_time = t - s.start_time;
    }
  }
  for (std::size_t i = 0; i < sc_.cones.size(); ++i) {
    out_.margins[i] = governor::pointing_margin(sc_.cones[i], R);
  }
  return out_;
}

std::vector<MissionSlew> MissionSlews::finish(double end_time) && {
  if (!slews_.empty()) slews_.back().end_time = end_time;
  return std::move(slews_);
}

}  // namespace attiguard::sim
