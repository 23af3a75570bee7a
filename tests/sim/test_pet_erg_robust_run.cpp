// The flight loop with robust margins (docs/pet-erg.md, sections 13-14) against the adversarial
// disturbance (sim/adversarial_disturbance.hpp): on random crafts, wheel arrays, cones, slews,
// sensor errors, delay and quantisation, the disturbance chosen at every control period (or at
// every evaluation of the vector field) to push V up and the axis towards the nearest cone, at its
// bound, never makes a run violate a constraint, and the true state's W stays below Γ_W.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <random>
#include <string>

#include "attiguard/core/errors.hpp"
#include "attiguard/lie/so3.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/read_pet_erg.hpp"
#include "attiguard/sim/pet_erg_run.hpp"
#include "sanitizer_build.hpp"

namespace attiguard::sim {
namespace {

using lie::Mat3;
using lie::Vec3;

std::string vec(const Vec3& v) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "[%.17g, %.17g, %.17g]", v(0), v(1), v(2));
  return buf;
}

std::string mat(const Mat3& m) {
  std::string out = "[";
  for (int i = 0; i < 3; ++i) {
    out += vec(m.row(i).transpose());
    out += i < 2 ? ", " : "]";
  }
  return out;
}

std::string num(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

struct Random {
  std::mt19937_64 gen;
  std::uniform_real_distribution<double> u{0.0, 1.0};
  std::normal_distribution<double> n{0.0, 1.0};
  explicit Random(std::uint64_t seed) : gen(seed) {}
  double uniform(double lo, double hi) { return lo + (hi - lo) * u(gen); }
  Vec3 unit() { return Vec3(n(gen), n(gen), n(gen)).normalized(); }
};

/// A random flight-like scenario with `margins` and an adversarial disturbance at its bound.
std::string random_scenario(Random& r, const std::string& margins, int index) {
  Vec3 d(r.uniform(60.0, 200.0), r.uniform(60.0, 200.0), r.uniform(60.0, 200.0));
  std::sort(d.data(), d.data() + 3);
  d(2) = std::min(d(2), d(0) + d(1));
  const Mat3 Q = lie::exp(3.0 * r.unit());
  const Mat3 J = Q * d.asDiagonal() * Q.transpose();
  const double kp = r.uniform(0.3, 1.5);
  const double kd = r.uniform(4.0, 10.0);
  std::string s = "kind = \"pet_erg\"\nname = \"robust_adversary_" + std::to_string(index) + "\"\ngovernor = \"pet\"\n";
  s += "[body]\ninertia = " + mat(J) + "\n";
  s += "[initial]\nattitude = { matrix = " + mat(lie::exp(0.1 * r.uniform(0.0, 1.0) * r.unit())) + " }\n";
  s += "omega_b = " + vec(1e-3 * r.uniform(0.0, 1.0) * r.unit()) + "\n";
  s += "[desired]\nattitude = { axis = " + vec(r.unit()) + ", angle_deg = " + num(r.uniform(30.0, 170.0)) + " }\n";
  s += "[control]\nkp = " + num(kp) + "\nkd = " + num(kd) + "\ntau_max = 1.0\ncontrol_period = 0.1\nmargins = \"" +
       margins + "\"\n";
  s += "[erg]\nkappa = " + num(r.uniform(2.0, 50.0)) + "\nsampling_period = " + num(r.uniform(0.2, 2.0)) + "\n";
  const int cones = 1 + static_cast<int>(r.uniform(0.0, 2.999));
  for (int i = 0; i < cones; ++i) {
    const bool out = r.uniform(0.0, 1.0) < 0.75;
    s += "[[cones]]\ntype = \"" + std::string(out ? "keep_out" : "keep_in") + "\"\naxis_b = " + vec(r.unit()) +
         "\ndirection_i = " + vec(r.unit()) + "\nhalf_angle_deg = " +
         num(out ? r.uniform(10.0, 35.0) : r.uniform(70.0, 110.0)) +
         "\ndelta_offset = " + num(r.uniform(0.002, 0.05)) + "\nrepulsive_gain = " + num(r.uniform(0.1, 1.0)) + "\n";
  }
  const double elevation = r.uniform(20.0, 50.0) * std::numbers::pi / 180.0;
  for (int i = 0; i < 4; ++i) {
    const double az = (0.25 + 0.5 * i) * std::numbers::pi;
    const Vec3 axis(std::cos(elevation) * std::cos(az), std::cos(elevation) * std::sin(az), std::sin(elevation));
    s += "[[wheels]]\naxis_b = " + vec(axis) + "\ntorque_max = " + num(r.uniform(0.08, 0.2)) +
         "\nmomentum_max = 20.0\n";
  }
  const bool continuous = index % 4 == 3;
  s += "[imperfections]\ndisturbance = \"adversarial\"\ndisturbance_bound = " + num(r.uniform(2e-4, 2e-3)) +
       "\nadversary_weight = " + num(index % 3 == 0 ? 1.0 : index % 3 == 1 ? 0.5 : 0.0) +
       "\ndisturbance_update = \"" + (continuous ? "continuous" : "control") + "\"\n";
  s += "attitude_bias = " + vec(r.uniform(0.0, 0.01) * r.unit()) + "\nattitude_noise = " + num(r.uniform(0.0, 3e-4)) +
       "\nrate_bias = " + vec(r.uniform(0.0, 2e-5) * r.unit()) + "\nrate_noise = " + num(r.uniform(0.0, 2e-5)) +
       "\ndelay_periods = " + std::to_string(index % 2) + "\ntorque_quantum = " + num(r.uniform(0.0, 1e-3)) +
       "\nseed = " + std::to_string(index) + "\n";
  s += "[simulation]\nduration = 300.0\noutput_interval = 300.0\nintegrator = \"rkmk4\"\nstep = 0.1\n"
       "convergence_tolerance = 1e-3\n";
  return s;
}

TEST(PetErgRobust, TheAdversarialDisturbanceNeverMakesARobustRunViolateAConstraint) {
  int runs = 0;
  int refused = 0;
  int nominal_violations = 0;
  for (int index = 0; index < 1500 && runs < attiguard::test::for_this_build(100, 25); ++index) {
    Random r(9000 + static_cast<std::uint64_t>(index));
    const std::string text = random_scenario(r, "robust", index);
    PetErgScenario sc;
    try {
      sc = scenario::parse_pet_erg(scenario::parse_document(text, "random_robust.toml"));
    } catch (const InputError& e) {
      if (std::getenv("ROBUST_WHY")) std::printf("refused: %s\n", e.what());
      ++refused;  // bounds leave no admissible set, R_d in a band, or a start outside the set
      continue;
    }
    ++runs;
    const PetErgResult res = simulate_pet_erg(sc);
    EXPECT_GE(res.min_pointing_margin, 0.0) << "scenario " << index << "\n" << text;
    EXPECT_LE(res.max_wheel_torque_ratio, 1.0) << "scenario " << index;
    EXPECT_LE(res.max_torque_norm, sc.params.tau_max) << "scenario " << index;
    EXPECT_LE(res.max_wheel_momentum_ratio, 1.0) << "scenario " << index << " (an assumption of the margins)";
    EXPECT_LE(res.max_V_minus_Gamma, 0.0) << "scenario " << index << ": W of the state seen through the bias";
    // The same scenario with the nominal margins, for the record.
    Random again(9000 + static_cast<std::uint64_t>(index));
    const PetErgScenario nominal =
        scenario::parse_pet_erg(scenario::parse_document(random_scenario(again, "nominal", index), "n.toml"));
    const PetErgResult rn = simulate_pet_erg(nominal);
    nominal_violations += (rn.min_pointing_margin < 0.0 || rn.max_wheel_torque_ratio > 1.0) ? 1 : 0;
  }
  EXPECT_GE(runs, attiguard::test::for_this_build(100, 25));
  RecordProperty("robust_runs", runs);
  RecordProperty("refused", refused);
  RecordProperty("nominal_runs_with_a_violation", nominal_violations);
  std::printf("[ figures  ] %d robust runs, 0 violations asserted; %d refused; nominal twins with a violation: %d\n",
              runs, refused, nominal_violations);
}

}  // namespace
}  // namespace attiguard::sim
