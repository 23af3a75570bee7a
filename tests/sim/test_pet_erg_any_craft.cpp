// PET-ERG runs with no governor or gain key (docs/pet-erg.md, section 8): every value derived
// from the craft. The three crafts of issue 41 (tests/data/defaults: a 3U CubeSat, a 2 t craft
// with wheels in a 10 Hz loop, a 10^6 kg m^2 station with wheels in a 1 Hz loop) converge with
// every constraint kept within 10x the eigenaxis bang-bang time; random crafts over
// J 10^-2..10^7 kg m^2 (moment ratios up to 10, products of inertia), torque 10^-4..10^2 N m,
// random cones (one craft in three with a keep-out cone centred on its eigenaxis path), continuous
// and flight loops with wheels and robust margins converge.
//
// The whole measurement (docs/pet-erg.md, section 8, "Measured"):
//   ATTIGUARD_ANY_CRAFT_RUNS=1000 build/tests/attiguard_tests --gtest_filter='PetErgAnyCraft.Random*'
// One craft of it: ATTIGUARD_ANY_CRAFT_FIRST=I ATTIGUARD_ANY_CRAFT_RUNS=1 ATTIGUARD_ANY_CRAFT_VERBOSE=1 …

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "attiguard/core/errors.hpp"
#include "attiguard/dynamics/eigenaxis_slew.hpp"
#include "attiguard/lie/so3.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/read_pet_erg.hpp"
#include "attiguard/sim/pet_erg_run.hpp"
#include "sanitizer_build.hpp"

namespace attiguard::sim::any_craft_test {
namespace {

using lie::Mat3;
using lie::Vec3;

constexpr double kDeg = std::numbers::pi / 180.0;

std::string num(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

std::string vec(const Vec3& v) { return "[" + num(v(0)) + ", " + num(v(1)) + ", " + num(v(2)) + "]"; }

std::string mat(const Mat3& m) {
  return "[" + vec(m.row(0).transpose()) + ", " + vec(m.row(1).transpose()) + ", " +
         vec(m.row(2).transpose()) + "]";
}

bool converged_with_constraints(const PetErgResult& r, const PetErgScenario& sc) {
  return r.outcome == PetErgOutcome::converged && !(r.min_pointing_margin < 0.0) &&
         r.max_torque_norm <= sc.params.tau_max && r.max_wheel_torque_ratio <= 1.0;
}

double bang_bang_time(const PetErgScenario& sc) {
  return dynamics::eigenaxis_bang_bang_time(sc.params.J, sc.R0_ib, sc.desired.at(sc.duration), sc.params.tau_max);
}

TEST(PetErgAnyCraft, IssueCraftsConvergeWithDefaultsWithinTenTimesBangBang) {
  const std::filesystem::path dir = std::filesystem::path(ATTIGUARD_SOURCE_DIR) / "tests/data/defaults";
  for (const char* name : {"cubesat_3u.toml", "craft_2t_wheels.toml", "station_wheels.toml"}) {
    const PetErgScenario sc = scenario::parse_pet_erg(scenario::load_document(dir / name));
    EXPECT_TRUE(sc.derived.kp_derived && sc.derived.kd_derived && sc.derived.kappa_derived &&
                sc.derived.Ts_derived && sc.derived.c_gamma_derived)
        << name;
    const PetErgResult r = simulate_pet_erg(sc);
    EXPECT_TRUE(converged_with_constraints(r, sc)) << name << ": " << kPetErgOutcomeNames.name(r.outcome);
    const double t_bb = bang_bang_time(sc);
    ASSERT_GT(t_bb, 0.0);
    EXPECT_LE(r.convergence_time, 10.0 * t_bb) << name;
    std::printf("[ figures  ] %s: converged at %.4g s = %.3gx the eigenaxis bang-bang time %.4g s, "
                "max |tau|/tau_max %.3g\n",
                name, r.convergence_time, r.convergence_time / t_bb, t_bb, r.max_torque_norm / sc.params.tau_max);
  }
}

TEST(PetErgAnyCraft, SymmetricSunConvergesWithDefaultsAndTheTieBreakInBothLoops) {
  const std::filesystem::path dir = std::filesystem::path(ATTIGUARD_SOURCE_DIR) / "tests/data/defaults";
  // cubesat_symmetric_5hz.toml: a slow loop deriving ε > 1 (it stalled while ε was the
  // tie-break's floor on ‖ρ_a‖ ≤ 1).
  for (const char* name : {"symmetric_sun.toml", "symmetric_sun_robust.toml", "cubesat_symmetric_5hz.toml"}) {
    const PetErgScenario sc = scenario::parse_pet_erg(scenario::load_document(dir / name));
    EXPECT_TRUE(sc.derived.kp_derived && sc.derived.kappa_derived) << name;
    const PetErgResult r = simulate_pet_erg(sc);
    EXPECT_TRUE(converged_with_constraints(r, sc)) << name << ": " << kPetErgOutcomeNames.name(r.outcome);
    EXPECT_GE(r.saddle_tie_breaks, 1) << name;
    const nlohmann::json summary = pet_erg_summary(sc, r);
    EXPECT_GE(summary.at("saddle_tie_breaks").get<long>(), 1) << name;
    EXPECT_LE(r.convergence_time, 10.0 * bang_bang_time(sc)) << name;
    std::printf("[ figures  ] %s: converged at %.4g s = %.3gx bang-bang, tie-break at %.4g s\n", name,
                r.convergence_time, r.convergence_time / bang_bang_time(sc), r.first_tie_break_time);
  }
}

// docs/pet-erg.md, section 4, "Half-turns": a slew of exactly π (R_d given as a matrix, so that
// sk(R_0ᵀR_d) = 0 exactly) left R_g at P_a's maximum for ever ("stalled, reference 180 deg short").
// A CubeSat, a 2 t craft with products of inertia and a station, in the continuous and the flight
// loop, each about two body axes, with a keep-out cone off the way: all converge with every
// value derived and the constraints kept.
TEST(PetErgAnyCraft, ExactHalfTurnsConvergeWithDefaultsAcrossCrafts) {
  struct Craft {
    const char* name;
    Mat3 J;
    double tau;
  };
  Mat3 J2t;
  J2t << 2000.0, 50.0, -30.0, 50.0, 1800.0, 20.0, -30.0, 20.0, 2400.0;
  const Craft crafts[] = {{"cubesat", Vec3(0.03, 0.035, 0.01).asDiagonal(), 2e-3},
                          {"craft_2t", J2t, 0.4},
                          {"station", Vec3(4e6, 5e6, 7e6).asDiagonal(), 2.0}};
  for (const Craft& c : crafts) {
    for (const Vec3& axis : {Vec3(0.0, 0.0, 1.0), Vec3(1.0, 0.0, 0.0)}) {
      for (bool flight : {false, true}) {
        Mat3 R_d = -Mat3::Identity();
        R_d += 2.0 * axis * axis.transpose();
        const double t_bb = dynamics::eigenaxis_bang_bang_time(c.J, Mat3::Identity(), R_d, c.tau);
        std::string s = "kind = \"pet_erg\"\nname = \"half_turn\"\n[body]\ninertia = " + mat(c.J) + "\n";
        s += "[initial]\nattitude = { matrix = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]] }\n";
        s += "[desired]\nattitude = { matrix = " + mat(R_d) + " }\n";
        s += "[control]\ntau_max = " + num(c.tau) + "\n";
        if (flight) s += "control_period = " + num(t_bb / 300.0) + "\n";
        // a cone on the body axis that the half turn does not move (its direction away from both ends)
        s += "[[cones]]\ntype = \"keep_out\"\naxis_b = " + vec(axis) + "\ndirection_i = " +
             vec(Vec3(axis + 2.0 * axis.unitOrthogonal()).normalized()) + "\nhalf_angle_deg = 15.0\n";
        s += "[simulation]\nduration = " + num(40.0 * t_bb) + "\noutput_interval = " + num(0.8 * t_bb) + "\n";
        const PetErgScenario sc = scenario::parse_pet_erg(scenario::parse_document(s, "half_turn.toml"));
        ASSERT_EQ(lie::distance(sc.R0_ib, sc.desired.at(0.0)), std::numbers::pi);
        const PetErgResult r = simulate_pet_erg(sc);
        EXPECT_TRUE(converged_with_constraints(r, sc))
            << c.name << (flight ? " flight" : " continuous") << ": " << kPetErgOutcomeNames.name(r.outcome);
        EXPECT_LE(r.convergence_time, 30.0 * t_bb) << c.name;
        std::printf("[ figures  ] half turn, %s about %s, %s: converged at %.4g s = %.3gx bang-bang\n", c.name,
                    axis(2) == 1.0 ? "z" : "x", flight ? "flight loop" : "continuous", r.convergence_time,
                    r.convergence_time / t_bb);
      }
    }
  }
}

struct Random {
  std::mt19937_64 gen;
  std::uniform_real_distribution<double> u{0.0, 1.0};
  std::normal_distribution<double> n{0.0, 1.0};
  explicit Random(std::uint64_t seed) : gen(seed) {}
  double uniform(double lo, double hi) { return lo + (hi - lo) * u(gen); }
  double log_uniform(double lo, double hi) { return std::exp(uniform(std::log(lo), std::log(hi))); }
  Vec3 unit() { return Vec3(n(gen), n(gen), n(gen)).normalized(); }
};

/// What a random craft flies with.
enum class Loop { continuous, flight, flight_wheels, robust };

const char* loop_name(Loop l) {
  switch (l) {
    case Loop::continuous: return "continuous";
    case Loop::flight: return "flight loop";
    case Loop::flight_wheels: return "flight loop with wheels";
    case Loop::robust: return "flight loop with wheels and robust margins";
  }
  return "?";
}

/// A random craft and slew of the class of issue 41, with no governor or gain key.
std::string random_craft(Random& r, Loop loop, int index) {
  const double J_max = r.log_uniform(1e-2, 1e7);
  const double J_min = J_max / r.log_uniform(1.0, 10.0);
  const double J_mid = r.uniform(std::max(J_min, J_max - J_min), J_max);
  const Mat3 Q = lie::exp(3.0 * r.unit());
  const Mat3 J = Q * Vec3(J_max, J_mid, J_min).asDiagonal() * Q.transpose();
  const double tau = r.log_uniform(std::max(1e-4, 1e-6 * J_max), std::min(1e2, J_max));
  const double theta = r.uniform(20.0, 170.0) * kDeg;
  const Mat3 R0 = lie::exp(3.0 * r.unit());
  const Vec3 axis = r.unit();
  const double t_bb = 2.0 * std::sqrt(theta * J_max / tau);
  std::string s = "kind = \"pet_erg\"\nname = \"any_craft_" + std::to_string(index) + "\"\n";
  s += "[body]\ninertia = " + mat(J) + "\n";
  s += "[initial]\nattitude = { matrix = " + mat(R0) + " }\n";
  s += "[desired]\nattitude = { matrix = " + mat(R0 * lie::exp(theta * axis)) + " }\n";
  s += "[control]\ntau_max = " + num(tau) + "\n";
  if (loop != Loop::continuous) {
    // robust margins bound the hold error k_d h ω̇: they need a loop fast against the craft
    const double per_slew = loop == Loop::robust ? r.log_uniform(1000.0, 4000.0) : r.log_uniform(100.0, 1000.0);
    const double h = std::clamp(t_bb / per_slew, 0.01, 1.0);
    s += "control_period = " + num(h) + "\n";
    if (loop == Loop::robust) s += "margins = \"robust\"\n";
  }
  const int keep_out = 1 + static_cast<int>(r.uniform(0.0, 2.999));
  // one craft in three has its first keep-out cone centred exactly on the eigenaxis path of its
  // body axis (the Sun between start and target: a saddle of the navigation field)
  const bool on_path = index % 3 == 1;
  for (int i = 0; i < keep_out; ++i) {
    const Vec3 axis_b = r.unit();
    Vec3 direction_i = r.unit();
    if (on_path && i == 0) direction_i = R0 * lie::exp(0.5 * theta * axis) * axis_b;
    s += "[[cones]]\ntype = \"keep_out\"\naxis_b = " + vec(axis_b) + "\ndirection_i = " + vec(direction_i) +
         "\nhalf_angle_deg = " + num(r.uniform(10.0, 30.0)) + "\n";
  }
  if (r.uniform(0.0, 1.0) < 0.3) {
    s += "[[cones]]\ntype = \"keep_in\"\naxis_b = " + vec(r.unit()) + "\ndirection_i = " + vec(r.unit()) +
         "\nhalf_angle_deg = " + num(r.uniform(80.0, 110.0)) + "\n";
  }
  if (loop == Loop::flight_wheels || loop == Loop::robust) {
    const double elevation = r.uniform(25.0, 45.0) * kDeg;
    const double wheel_torque = tau * r.uniform(0.4, 0.9);
    const double momentum = 3.0 * J_max * std::sqrt(theta * tau / J_max);  // 3x the bang-bang peak
    for (int i = 0; i < 4; ++i) {
      const double az = (0.25 + 0.5 * i) * std::numbers::pi;
      const Vec3 w(std::cos(elevation) * std::cos(az), std::cos(elevation) * std::sin(az), std::sin(elevation));
      s += "[[wheels]]\naxis_b = " + vec(w) + "\ntorque_max = " + num(wheel_torque) + "\nmomentum_max = " +
           num(momentum) + "\n";
    }
  }
  if (loop == Loop::robust) {
    s += "[imperfections]\ndisturbance = \"constant\"\ndisturbance_axis_b = " + vec(r.unit()) +
         "\ndisturbance_bound = " + num(0.01 * tau) + "\nattitude_noise = 1e-5\nseed = " + std::to_string(index) + "\n";
  }
  s += "[simulation]\nduration = " + num(30.0 * t_bb) + "\noutput_interval = " + num(30.0 * t_bb / 50.0) + "\n";
  return s;
}

TEST(PetErgAnyCraft, RandomCraftsConvergeWithDefaults) {
  long wanted = attiguard::test::for_this_build(32, 8);
  if (const char* e = std::getenv("ATTIGUARD_ANY_CRAFT_RUNS")) wanted = std::max(1L, std::atol(e));
  const bool verbose = std::getenv("ATTIGUARD_ANY_CRAFT_VERBOSE") != nullptr;
  long runs = 0, converged = 0, violations = 0, refused = 0, tie_broken = 0;
  std::vector<double> ratios;
  std::map<std::string, long> not_converged;
  // ATTIGUARD_ANY_CRAFT_FIRST=I starts at draw I (to replay one craft of the measurement)
  const int first = std::getenv("ATTIGUARD_ANY_CRAFT_FIRST") ? std::atoi(std::getenv("ATTIGUARD_ANY_CRAFT_FIRST")) : 0;
  for (int index = first; runs < wanted && index < first + 50 * wanted; ++index) {
    Random r(41000 + static_cast<std::uint64_t>(index));
    const Loop loop = static_cast<Loop>(index % 4);
    const std::string text = random_craft(r, loop, index);
    PetErgScenario sc;
    try {
      sc = scenario::parse_pet_erg(scenario::parse_document(text, "any_craft.toml"));
    } catch (const InputError& e) {
      ++refused;  // a cone over R_0 or R_d, or robust bounds that leave no admissible set
      if (verbose) std::printf("refused %d: %s\n", index, e.what());
      continue;
    }
    ++runs;
    const PetErgResult res = simulate_pet_erg(sc);
    const bool kept = !(res.min_pointing_margin < 0.0) && res.max_torque_norm <= sc.params.tau_max &&
                      res.max_wheel_torque_ratio <= 1.0;
    violations += kept ? 0 : 1;
    EXPECT_TRUE(kept) << "craft " << index << " (" << loop_name(loop) << ")\n" << text;
    tie_broken += res.saddle_tie_breaks > 0 ? 1 : 0;
    if (res.outcome == PetErgOutcome::converged) {
      ++converged;
      ratios.push_back(res.convergence_time / bang_bang_time(sc));
    } else {
      ++not_converged[std::string(kPetErgOutcomeNames.name(res.outcome))];
      std::printf("craft %d (%s) %s: %s\n", index, loop_name(loop),
                  std::string(kPetErgOutcomeNames.name(res.outcome)).c_str(),
                  pet_erg_summary(sc, res).value("outcome_reason", std::string()).c_str());
      if (verbose) std::printf("%s\n", text.c_str());
    }
  }
  std::sort(ratios.begin(), ratios.end());
  const auto quantile = [&](double q) {
    return ratios.empty() ? std::nan("") : ratios[static_cast<std::size_t>(q * static_cast<double>(ratios.size() - 1))];
  };
  std::printf("[ figures  ] %ld random crafts (%ld refused at set-up): %ld converged, %ld with a violation, "
              "%ld with a saddle tie-break; convergence / bang-bang median %.3g, p90 %.3g, max %.3g\n",
              runs, refused, converged, violations, tie_broken, quantile(0.5), quantile(0.9), quantile(1.0));
  for (const auto& [outcome, count] : not_converged) std::printf("[ figures  ]   %s: %ld\n", outcome.c_str(), count);
  EXPECT_EQ(runs, wanted);
  EXPECT_EQ(violations, 0);
  // ≥ 99 % over the 1000 of docs/pet-erg.md; the suite's few dozen allow one miss
  EXPECT_GE(static_cast<double>(converged), std::min(0.99 * static_cast<double>(runs), static_cast<double>(runs - 1)));
}

}  // namespace
}  // namespace attiguard::sim::any_craft_test
