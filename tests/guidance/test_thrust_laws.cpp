// Thrust laws (13), (15)-(16) of the waypoint paper and the erratum of (15).
#include <gtest/gtest.h>

#include <cmath>

#include "attiguard/guidance/thrust_laws.hpp"

namespace attiguard::guidance {
namespace {

struct Braking {
  double final_distance;  ///< e when v reached 0 (negative: overshoot)
  double speed_at_waypoint;  ///< v when e crossed 0 (0 if it stopped short)
};

/// 1-D approach at v0 from e0 with the deceleration law sampled every Ts (zero-order hold).
template <class Law>
Braking approach(Law law, double e0, double v0, double Ts) {
  const double m = 100.0, T_max = 20.0;
  double e = e0, v = v0;
  for (int k = 0; k < 10'000'000; ++k) {
    const double a = law(m, v, e, T_max) / m;
    const double v_next = std::max(v - a * Ts, 0.0);
    const double dt = v > v_next && v_next == 0.0 ? v / a : Ts;
    const double e_next = e - 0.5 * (v + v_next) * dt;
    if (e > 0.0 && e_next <= 0.0 && v_next > 0.0) return {e_next, v};
    e = e_next;
    v = v_next;
    if (v <= 1e-12) return {e, 0.0};
  }
  return {e, v};
}

TEST(ThrustLaws, AccelerationLawIsBangBangOnTheCruiseSpeed) {
  EXPECT_EQ(acceleration_thrust(10.0, 50.0, 20.0), 20.0);
  EXPECT_EQ(acceleration_thrust(50.0, 50.0, 20.0), 20.0);
  EXPECT_EQ(acceleration_thrust(50.1, 50.0, 20.0), 0.0);
}

TEST(ThrustLaws, CorrectedDecelerationStopsAtTheWaypoint) {
  // From the paper's cruise speed (56.6 m/s, 20 % of 40 km at 0.2 m/s²), coasting from 32 km.
  auto law = [](double m, double v, double e, double T) { return deceleration_thrust(m, v, e, T, 0.95); };
  const Braking b = approach(law, 32000.0, 56.57, 0.1);
  EXPECT_LT(std::abs(b.final_distance), 0.05);
  EXPECT_LT(b.speed_at_waypoint, 0.05);
}

TEST(ThrustLaws, MarginOneLeavesTheSampledOvershootBound) {
  // γ = 1 (16) as printed: braking starts up to one period late, so the waypoint is reached
  // with up to √(2 a v Ts) left.
  auto law = [](double m, double v, double e, double T) { return deceleration_thrust(m, v, e, T, 1.0); };
  const Braking b = approach(law, 32000.0, 56.57, 0.1);
  EXPECT_LE(b.speed_at_waypoint, std::sqrt(2.0 * 0.2 * 56.57 * 0.1) + 1e-9);
}

TEST(ThrustLaws, Erratum15PrintedLawFiresFarTooLate) {
  // (15) as printed, a_d = ‖v‖/(2‖e‖), is not an acceleration: it fires only at ‖e‖ ≤ 2.5 ‖v‖
  // and passes the waypoint at nearly full speed.
  const Braking b = approach(deceleration_thrust_as_printed, 32000.0, 56.57, 0.1);
  EXPECT_GT(b.speed_at_waypoint, 50.0);
  EXPECT_DOUBLE_EQ(braking_deceleration(10.0, 250.0), 0.2);  // v²/(2e)
}

}  // namespace
}  // namespace attiguard::guidance
