// Mission state machine: feed-forward along simulated legs, singular configurations, and a sweep
// of random initial states and waypoint lists.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "attiguard/guidance/mission.hpp"
#include "attiguard/sim/waypoint_run.hpp"
#include "test_support.hpp"

namespace attiguard::guidance {
namespace {

using lie::Quat;

sim::WaypointScenario short_leg_scenario() {
  sim::WaypointScenario sc;
  sc.name = "leg";
  sc.mission.pointing_tolerance = 1e-4;
  sc.mission.pointing_thrust_axis = true;
  sc.mission.braking_margin = 0.95;
  sc.mission.arrival_radius = 0.005;
  sc.mission.position_accuracy = 0.2;
  sc.mission.speed_accuracy = 0.005;
  sc.mission.rct = {0.02, 0.5};
  sc.mission.flip_timing = FlipTiming::braking_point;
  sc.gains.integral_zone = 0.05;
  sc.duration = 900.0;
  sc.integrator.step = 0.1;
  return sc;
}

Vec3 fd_rate(Quat qm, const Quat& q, Quat qp, double h) {
  if (qp.dot(q) < 0) qp = -qp;
  if (qm.dot(q) < 0) qm = -qm;
  return 2.0 * lie::quat_multiply(lie::quat_conjugate(q), (qp - qm) / (2.0 * h)).tail<3>();
}

struct FdStats {
  int checked{0};
  int near_parallel{0};     ///< error-frame angle to its chart < 1e-3 rad
  int antiparallel_leg{0};  ///< samples of a leg whose direction is antiparallel to the start x_b
  double worst_rel{0.0};
};

/// Runs the scenario and compares, at every guided sample, the feed-forward rates of the error
/// frame, the velocity frame and the composite (24) with central differences of the frames along
/// the trajectory (p ± h v + h² a/2, v ± h a with the acceleration the held commands produce).
FdStats check_feedforward(const sim::WaypointScenario& sc, bool antiparallel) {
  FdStats st;
  const double h = 1e-4;
  auto observer = [&](double, const dynamics::SpacecraftState& y, const MissionCommand& cmd) {
    if (cmd.mode == Mode::fine || cmd.mode == Mode::done) return;
    const Vec3 p = dynamics::p_i_of(y), v = dynamics::v_i_of(y);
    const Vec3 a = y.R[0] * (Vec3(cmd.inputs.thrust, 0, 0) + cmd.inputs.f_rct_b) / sc.mission.mass;
    const Vec3& wp = sc.waypoints_i[static_cast<std::size_t>(cmd.waypoint)];
    auto at = [&](double t) { return desired_attitude(cmd.spec, wp, p + v * t + 0.5 * a * t * t, v + a * t, a); };
    const DesiredAttitude d0 = at(0.0), dm = at(-h), dp = at(h);
    ASSERT_LT((d0.q_id - cmd.q_id).norm(), 1e-12);  // the mission used exactly this frame
    ASSERT_LT((d0.omega_d - cmd.omega_d_d).norm(), 1e-12);
    const std::array<std::pair<Vec3, Vec3>, 3> pairs{{
        {d0.error.omega_e, fd_rate(dm.error.q_ie, d0.error.q_ie, dp.error.q_ie, h)},
        {d0.velocity.omega_d, fd_rate(dm.velocity.q_ed, d0.velocity.q_ed, dp.velocity.q_ed, h)},
        {d0.omega_d, fd_rate(dm.q_id, d0.q_id, dp.q_id, h)},
    }};
    for (const auto& [ff, fd] : pairs) {
      const double err = (ff - fd).norm();
      // Relative error < 1e-5; rates below 1e-6 rad/s are compared absolutely to 1e-11 rad/s,
      // the round-off of the central difference (≈ 2·1e-16/h = 2e-12 rad/s).
      EXPECT_LT(err, 1e-5 * std::max(fd.norm(), 1e-6)) << "mode " << mode_name(cmd.mode);
      if (fd.norm() > 1e-6) st.worst_rel = std::max(st.worst_rel, err / fd.norm());
    }
    ++st.checked;
    if (d0.error.cos_chart > std::cos(1e-3)) ++st.near_parallel;
    if (antiparallel) ++st.antiparallel_leg;
  };
  const sim::WaypointSimResult res = sim::simulate_waypoint(sc, observer);
  EXPECT_TRUE(res.finite);
  return st;
}

TEST(MissionFeedForward, MatchesFiniteDifferencesAlongASimulatedLegWithLateralDrift) {
  sim::WaypointScenario sc = short_leg_scenario();
  sc.v0_i = Vec3(0.0, 1.5, -1.0);  // lateral drift: the error direction turns during the leg
  sc.waypoints_i = {Vec3(3000.0, 0.0, 0.0)};
  const FdStats st = check_feedforward(sc, false);
  EXPECT_GT(st.checked, 1000);
  EXPECT_GT(st.near_parallel, 0);  // the leg starts with ϑ = 0 (parallel case of (11))
  RecordProperty("worst_relative_error", std::to_string(st.worst_rel));
  std::printf("feed-forward: %d samples, worst relative error %.3g\n", st.checked, st.worst_rel);
}

TEST(MissionFeedForward, MatchesFiniteDifferencesOnALegAntiparallelToTheBodyAxis) {
  // The waypoint lies along −x_b and −x_i: the paper's chart (inertial x) has ϑ = π exactly
  // (k of (11) undefined); the reversed vector of the deceleration is again antiparallel.
  sim::WaypointScenario sc = short_leg_scenario();
  sc.v0_i = Vec3(0.0, 0.3, 0.2);
  sc.waypoints_i = {Vec3(-3000.0, 0.0, 0.0)};
  const FdStats st = check_feedforward(sc, true);
  EXPECT_GT(st.checked, 1000);
  EXPECT_GT(st.antiparallel_leg, 1000);
  std::printf("feed-forward (antiparallel leg): %d samples, worst relative error %.3g\n", st.checked,
              st.worst_rel);
}

TEST(MissionStateMachine, EveryLegRunsTheModesInOrder) {
  sim::WaypointScenario sc = short_leg_scenario();
  sc.waypoints_i = {Vec3(2000.0, 0.0, 0.0), Vec3(2000.0, 2000.0, 0.0)};
  sc.duration = 2000.0;
  const sim::WaypointSimResult res = sim::simulate_waypoint(sc);
  ASSERT_TRUE(res.completed);
  // align → accelerate → coast → flip → decelerate → fine → (align | done), per waypoint.
  const std::array<Mode, 6> order{Mode::align, Mode::accelerate, Mode::coast, Mode::flip,
                                  Mode::decelerate, Mode::fine};
  std::size_t k = 0;
  for (const sim::TransitionRecord& r : res.transitions) {
    EXPECT_EQ(r.from, order[k % 6]) << "transition " << k;
    ++k;
  }
  EXPECT_EQ(k, 12u);
  EXPECT_EQ(res.transitions.back().to, Mode::done);
}

TEST(MissionSweep, NoNanForRandomInitialStatesAndWaypointLists) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  auto& g = test::rng();
  int completed = 0;
  long brake_samples = 0;
  for (int trial = 0; trial < 1000; ++trial) {
    sim::WaypointScenario sc;
    sc.name = "sweep";
    sc.R0_ib = test::random_rotation();
    sc.omega0_b = test::random_vector_in_ball(1.0);
    sc.p0_i = test::random_vector_in_ball(100.0);
    sc.v0_i = test::random_vector_in_ball(u(g) < 0.2 ? 0.0 : 5.0);
    const int n = 1 + static_cast<int>(u(g) * 3.0);
    for (int i = 0; i < n; ++i) {
      // Include duplicates, waypoints on the start point and tiny legs.
      const double r = u(g);
      sc.waypoints_i.push_back(r < 0.1 ? sc.p0_i : (r < 0.2 ? sc.p0_i + test::random_vector_in_ball(0.01)
                                                            : test::random_vector_in_ball(400.0)));
    }
    sc.mission.pointing_tolerance = u(g) < 0.5 ? 1e-6 : 1e-3;
    sc.mission.pointing_thrust_axis = u(g) < 0.5;
    sc.mission.velocity_projection = u(g) < 0.8;
    sc.mission.flip_timing = u(g) < 0.5 ? FlipTiming::immediate : FlipTiming::braking_point;
    sc.mission.braking_margin = 0.9 + 0.1 * u(g);
    sc.mission.brake_along_velocity = u(g) < 0.7;
    sc.mission.rct.kappa_p = u(g) < 0.5 ? 0.0 : 0.02;
    sc.mission.arrival_radius = 0.01;
    sc.mission.position_accuracy = 0.5;
    sc.mission.speed_accuracy = 0.01;
    sc.max_wheel_torque = u(g) < 0.3 ? 2.0 : 0.0;
    // Beyond the paper: brake mode on/off, a zero cut-off speed, a main engine up to 5 deg off.
    sc.mission.brake_speed = u(g) < 0.3 ? 0.0 : 0.05 + u(g);
    sc.mission.main_cutoff_speed = u(g) < 0.2 ? 0.0 : 0.02;
    sc.mission.replan_distance = u(g) < 0.5 ? 50.0 : 5.0;
    const double tilt = 5.0 * M_PI / 180.0 * u(g);
    const double around = 2.0 * M_PI * u(g);
    sc.main_thrust_axis_b = Vec3(std::cos(tilt), std::sin(tilt) * std::cos(around),
                                 std::sin(tilt) * std::sin(around));
    sc.duration = 120.0;
    sc.integrator.step = 0.1;
    double worst = 0.0;
    const sim::WaypointSimResult res = sim::simulate_waypoint(
        sc, [&](double, const dynamics::SpacecraftState& y, const MissionCommand& c) {
          ASSERT_TRUE(y.all_finite());
          ASSERT_TRUE(c.q_id.allFinite() && c.omega_d_d.allFinite() && c.inputs.tau_b.allFinite());
          worst = std::max(worst, c.omega_d_d.norm());
          brake_samples += c.mode == Mode::brake ? 1 : 0;
        });
    ASSERT_TRUE(res.finite) << "trial " << trial;
    ASSERT_TRUE(std::isfinite(worst));
    completed += res.completed ? 1 : 0;
  }
  RecordProperty("completed_within_120s", completed);
  EXPECT_GT(brake_samples, 0);  // the brake mode was exercised
}

}  // namespace
}  // namespace attiguard::guidance
