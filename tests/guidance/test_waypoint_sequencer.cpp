// Waypoint sequencer (guidance::WaypointSequencer): feed-forward along simulated legs, singular configurations, and a sweep
// of random initial states and waypoint lists.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "attiguard/guidance/waypoint_sequencer.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/read_waypoint.hpp"
#include "attiguard/sim/waypoint_run.hpp"
#include "sanitizer_build.hpp"
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

Vec3 mission_fd_rate(Quat qm, const Quat& q, Quat qp, double h) {
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
        {d0.error.omega_e, mission_fd_rate(dm.error.q_ie, d0.error.q_ie, dp.error.q_ie, h)},
        {d0.velocity.omega_d, mission_fd_rate(dm.velocity.q_ed, d0.velocity.q_ed, dp.velocity.q_ed, h)},
        {d0.omega_d, mission_fd_rate(dm.q_id, d0.q_id, dp.q_id, h)},
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

// Issue 42: the miss distance is the distance of closest approach of the straight line p + v t,
// found here by brute force along the line; not closing is +∞.
TEST(WaypointSequencerGeometry, MissDistanceIsTheClosestApproachOfTheStraightLine) {
  const Vec3 e(120.0, -40.0, 15.0);
  for (const Vec3& v : {Vec3(1.0, -0.2, 0.3), Vec3(0.5, -0.1, 0.05), Vec3(3.0, -1.0, 0.375)}) {
    double best = e.norm();
    for (int k = 0; k <= 400000; ++k) {
      const double t = 1e-3 * k * (e.dot(v) / v.squaredNorm()) * 2.0 / 400.0;
      best = std::min(best, (e - v * t).norm());
    }
    EXPECT_NEAR(miss_distance(e, v), best, 1e-6 * e.norm()) << v.transpose();
  }
  EXPECT_TRUE(std::isinf(miss_distance(e, Vec3(-1.0, 0.0, 0.0))));
  EXPECT_EQ(miss_distance(Vec3::Zero(), Vec3(1.0, 0.0, 0.0)), 0.0);
}

TEST(WaypointSequencerFeedForward, MatchesFiniteDifferencesAlongASimulatedLegWithLateralDrift) {
  sim::WaypointScenario sc = short_leg_scenario();
  sc.v0_i = Vec3(0.0, 1.5, -1.0);  // lateral drift: the error direction turns during the leg
  sc.waypoints_i = {Vec3(3000.0, 0.0, 0.0)};
  const FdStats st = check_feedforward(sc, false);
  EXPECT_GT(st.checked, 1000);
  EXPECT_GT(st.near_parallel, 0);  // the leg starts with ϑ = 0 (parallel case of (11))
  RecordProperty("worst_relative_error", std::to_string(st.worst_rel));
  std::printf("feed-forward: %d samples, worst relative error %.3g\n", st.checked, st.worst_rel);
}

TEST(WaypointSequencerFeedForward, MatchesFiniteDifferencesOnALegAntiparallelToTheBodyAxis) {
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

TEST(WaypointSequencerStateMachine, EveryLegRunsTheModesInOrder) {
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

TEST(WaypointSequencerSweep, NoNanForRandomInitialStatesAndWaypointLists) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  auto& g = test::rng();
  int completed = 0;
  long brake_samples = 0;
  for (long trial = 0; trial < test::for_this_build(1000, 250); ++trial) {
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

namespace geometry {

/// A `waypoint` scenario (profile "craft": every guidance default derived from the craft) of the
/// issue-13 spacecraft with the given initial velocity and waypoint list.
sim::WaypointScenario craft_scenario(const std::string& velocity, const std::string& waypoints) {
  const std::string text = R"(kind = "waypoint"
[spacecraft]
mass = 100.0
inertia = [20, 20, 20]
main_thrust = 20.0
rct_thrust = 0.5
[initial]
velocity = )" + velocity + "\n" + waypoints + R"(
[guidance]
cruise_speed = 1.0
arrival_radius = 0.01
position_accuracy = 0.2
speed_accuracy = 0.005
[simulation]
duration = 4000
step = 0.1
)";
  return scenario::parse_waypoint(scenario::parse_document(text, "geometry.toml"));
}

double angle_between(const Quat& a, const Quat& b) {
  return 2.0 * std::acos(std::min(1.0, std::abs(a.dot(b))));
}

/// Modes whose entry keeps the desired attitude continuous (align, flip and brake are commanded
/// slews: their entry is a step of R_d by design).
bool continuous_entry(Mode m) {
  return m == Mode::accelerate || m == Mode::coast || m == Mode::decelerate || m == Mode::fine ||
         m == Mode::done;
}

}  // namespace geometry

TEST(WaypointSequencerGeometry, DesiredAttitudeAndRateFiniteAndContinuousInEveryGeometry) {
  struct Case {
    const char* name;
    const char* velocity;
    const char* waypoints;
  };
  const std::array<Case, 8> cases{{
      {"straight crossing", "[0, 0, 0]", "[[waypoints]]\nposition = [100, 0, 0]"},
      {"crossing at speed", "[2, 0, 0]", "[[waypoints]]\nposition = [60, 0, 0]"},
      {"reversal (waypoint behind)", "[1, 0, 0]", "[[waypoints]]\nposition = [-80, 0, 0]"},
      {"receding sideways", "[0.1, 0.5, 0]", "[[waypoints]]\nposition = [-50, 10, 0]"},
      {"collinear legs", "[0, 0, 0]",
       "[[waypoints]]\nposition = [50, 0, 0]\n[[waypoints]]\nposition = [120, 0, 0]"},
      {"anti-parallel legs", "[0, 0, 0]",
       "[[waypoints]]\nposition = [80, 0, 0]\n[[waypoints]]\nposition = [0, 0, 0]"},
      {"zero-length leg", "[0, 0, 0]",
       "[[waypoints]]\nposition = [60, 0, 0]\n[[waypoints]]\nposition = [60, 0, 0]"},
      {"starting on the waypoint", "[0, 0, 0]",
       "[[waypoints]]\nposition = [0, 0, 0]\n[[waypoints]]\nposition = [0, 40, 0]"},
  }};
  for (const Case& c : cases) {
    const sim::WaypointScenario sc = geometry::craft_scenario(c.velocity, c.waypoints);
    bool have_last = false;
    Quat q_last;
    lie::Vec3 v_last = lie::Vec3::Zero();
    double w_last = 0.0;
    Mode mode_last = Mode::align;
    int wp_last = 0;
    double worst_rate = 0.0;
    int jumps = 0;
    const sim::WaypointSimResult res = sim::simulate_waypoint(
        sc, [&](double t, const dynamics::SpacecraftState& y, const MissionCommand& cmd) {
          ASSERT_TRUE(cmd.q_id.allFinite() && cmd.omega_d_d.allFinite()) << c.name << " t = " << t;
          worst_rate = std::max(worst_rate, cmd.omega_d_d.norm());
          const bool same_leg = cmd.waypoint == wp_last;
          const bool continuous =
              same_leg && (cmd.transition ? geometry::continuous_entry(cmd.mode) : cmd.mode == mode_last);
          if (have_last && continuous) {
            // One period of the feed-forward (or, while braking, of the body and of v̂: x_d = −v̂
            // is re-aimed from the measured attitude) bounds the change of R_d.
            const lie::Vec3 v = dynamics::v_i_of(y);
            const double turn_of_v =
                cmd.mode == Mode::brake && v_last.norm() > 0.0 && v.norm() > 0.0
                    ? std::acos(std::clamp(v.normalized().dot(v_last.normalized()), -1.0, 1.0))
                    : 0.0;
            const double bound = 2.0 * sc.control_period *
                                     (w_last + cmd.omega_d_d.norm() + dynamics::omega_b_of(y).norm()) +
                                 1.5 * turn_of_v + 1e-6;
            if (geometry::angle_between(q_last, cmd.q_id) > bound) ++jumps;
            EXPECT_LE(geometry::angle_between(q_last, cmd.q_id), bound)
                << c.name << " t = " << t << " mode " << mode_name(cmd.mode);
          }
          have_last = true;
          v_last = dynamics::v_i_of(y);
          q_last = cmd.q_id;
          w_last = cmd.omega_d_d.norm();
          mode_last = cmd.mode;
          wp_last = cmd.waypoint;
        });
    EXPECT_TRUE(res.finite) << c.name;
    EXPECT_TRUE(res.completed) << c.name << ": " << res.total_time << " s";
    EXPECT_LT(worst_rate, 10.0) << c.name;
    for (const sim::WaypointResult& w : res.waypoints) {
      EXPECT_LT(w.final_position_error, sc.mission.position_accuracy) << c.name;
      EXPECT_LT(w.final_speed, sc.mission.speed_accuracy) << c.name;
    }
    std::printf("%-28s completed %d in %7.1f s, %zu transitions, max |omega_d| %.3g rad/s\n", c.name,
                res.completed ? 1 : 0, res.total_time, res.transitions.size(), worst_rate);
  }
}

}  // namespace
}  // namespace attiguard::guidance
