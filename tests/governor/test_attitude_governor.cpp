// The reference update laws (4)-(6) of the PET-ERG paper, the sampling clock, and the combined
// flight-loop API used from a hand-written loop (no simulator).

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>
#include <type_traits>
#include <vector>

#include "attiguard/core/errors.hpp"
#include "attiguard/governor/attitude_governor.hpp"
#include "attiguard/governor/continuous_erg.hpp"
#include "attiguard/governor/pet_erg.hpp"
#include "attiguard/governor/reference_schedule.hpp"
#include "test_support.hpp"

namespace attiguard::governor {
namespace {

using lie::Mat3;
using lie::Vec3;

// Per-step functions are noexcept (flight-loop requirement).
using CM = const Mat3&;
using CV = const Vec3&;
static_assert(noexcept(std::declval<AttitudeGovernor&>().step(0.0, std::declval<CM>(),
                                                              std::declval<CV>(),
                                                              std::declval<CM>())));
static_assert(noexcept(std::declval<const AttitudeGovernor&>().evaluate(
    std::declval<CM>(), std::declval<CV>(), std::declval<CM>(), std::declval<CM>(), true)));
static_assert(noexcept(std::declval<const AttitudeGovernor&>().rates(
    std::declval<CM>(), std::declval<CV>(), std::declval<CM>(), std::declval<CM>(), true)));
static_assert(noexcept(std::declval<const ReferenceSchedule&>().at(0.0)));

GovernorParams paper_params(GovernorMode mode = GovernorMode::pet) {
  GovernorParams p;
  p.mode = mode;
  p.gains = {5.0, 1.0};
  p.J = Vec3(1.0, 2.0, 3.0).asDiagonal();
  p.tau_max = 2.5;
  p.kappa = 1.0;
  p.c_gamma = 3.0;
  p.Ts = 0.5;
  p.epsilon = 1e-3;
  p.epsilon_gamma = 0.1;
  return p;
}

ConeConstraint paper_cone() {
  return keep_in_cone(Vec3(0, 0, 1), Vec3(-0.791, 0.061, -0.609), 160.0 * std::numbers::pi / 180.0);
}

TEST(ReferenceUpdate, ContinuousErgRateIsNormalisedAndVanishesOutsideTheMargin) {
  const Vec3 rho(0.3, -0.4, 1.2);
  const Vec3 xi = erg_reference_rate(2.0, 1.0, 0.25, rho, 1e-3);
  EXPECT_NEAR(xi.norm(), 2.0 * 0.75, 1e-12);
  EXPECT_NEAR(xi.normalized().dot(rho.normalized()), 1.0, 1e-12);
  // ‖ρ‖ < ε: the rate shrinks like ρ/ε.
  const Vec3 small = 1e-4 * rho.normalized();
  EXPECT_NEAR(erg_reference_rate(1.0, 1.0, 0.0, small, 1e-3).norm(), 0.1, 1e-12);
  EXPECT_EQ(erg_reference_rate(1.0, 1.0, 1.0, rho, 1e-3).norm(), 0.0);
  EXPECT_EQ(erg_reference_rate(1.0, 1.0, 2.0, rho, 1e-3).norm(), 0.0);
}

TEST(ReferenceUpdate, PetTriggerAndHeldRate) {
  EXPECT_TRUE(pet_trigger(3.0, 1.0, 3.0));
  EXPECT_FALSE(pet_trigger(2.99, 1.0, 3.0));
  const Vec3 rho(1, 0, 0);
  EXPECT_EQ(pet_reference_rate(false, 1.0, 1.0, 0.1, rho, 1e-3).norm(), 0.0);
  EXPECT_NEAR(pet_reference_rate(true, 1.0, 1.0, 0.1, rho, 1e-3).norm(), 0.9, 1e-15);
}

TEST(SamplingClock, FiresOnceAtEachInstantWhateverTheCallRate) {
  SamplingClock clock(0.0, 0.5);
  std::vector<double> fired;
  for (int i = 0; i <= 300; ++i) {
    const double t = i * 0.01;
    if (clock.poll(t)) {
      fired.push_back(t);
      EXPECT_NEAR(clock.last_sample(), std::round(t / 0.5) * 0.5, 1e-12);
    }
  }
  ASSERT_EQ(fired.size(), 7u);  // 0, 0.5, …, 3.0
  for (std::size_t k = 0; k < fired.size(); ++k) {
    EXPECT_NEAR(fired[k], 0.5 * static_cast<double>(k), 1e-9);
  }
  // Missed instants collapse into one.
  SamplingClock slow(0.0, 0.5);
  EXPECT_TRUE(slow.poll(0.0));
  EXPECT_TRUE(slow.poll(2.3));
  EXPECT_NEAR(slow.last_sample(), 2.0, 1e-12);
  EXPECT_NEAR(slow.next_sample(), 2.5, 1e-12);
  EXPECT_FALSE(slow.poll(2.4));
}

TEST(ReferenceSchedule, HoldAndGeodesicInterpolation) {
  const Mat3 A = lie::exp(Vec3(0.1, 0.2, 0.3));
  const Mat3 B = lie::exp(Vec3(-0.5, 0.4, 0.2));
  const std::vector<Waypoint> w{{1.0, A}, {3.0, B}};
  const ReferenceSchedule hold(w, Interpolation::hold);
  const ReferenceSchedule slew(w, Interpolation::geodesic);
  EXPECT_LE((hold.at(0.0) - A).norm(), 0.0);
  EXPECT_LE((hold.at(2.9) - A).norm(), 0.0);
  EXPECT_LE((hold.at(3.0) - B).norm(), 0.0);
  EXPECT_LE((slew.at(3.5) - B).norm(), 1e-15);
  const Mat3 mid = slew.at(2.0);
  EXPECT_NEAR(lie::distance(A, mid), 0.5 * lie::distance(A, B), 1e-12);
  EXPECT_NEAR(lie::distance(mid, B), 0.5 * lie::distance(A, B), 1e-12);
  EXPECT_THROW(ReferenceSchedule(std::vector<Waypoint>{{1.0, A}, {1.0, B}}, Interpolation::hold),
               SetupError);
}

// Issue 14: the first waypoint's t is honoured: before it R_d is the attitude given as R_before
// (the scenario's initial attitude), not the first waypoint.
TEST(ReferenceSchedule, FirstWaypointTimeIsHonoured) {
  const Mat3 R0 = lie::exp(Vec3(0.1, 0.2, -0.3));
  const Mat3 A = lie::exp(Vec3(0.0, 1.0, 0.0));
  const Mat3 B = lie::exp(Vec3(1.0, 0.0, 0.0));
  const std::vector<Waypoint> w{{5.0, A}, {10.0, B}};
  const ReferenceSchedule s(w, Interpolation::geodesic, R0);
  EXPECT_LT(lie::distance(s.at(0.0), R0), 1e-15);
  EXPECT_LT(lie::distance(s.at(4.999), R0), 1e-15);
  EXPECT_LT(lie::distance(s.at(5.0), A), 1e-15);
  EXPECT_LT(lie::distance(s.at(20.0), B), 1e-15);
  // Without R_before the first waypoint's attitude holds before its time (library default).
  EXPECT_LT(lie::distance(ReferenceSchedule(w, Interpolation::hold).at(0.0), A), 1e-15);
}

TEST(AttitudeGovernor, RejectsInvalidParameters) {
  GovernorParams p = paper_params();
  p.c_gamma = 1.0;
  const std::vector<ConeConstraint> cones{paper_cone()};
  EXPECT_THROW(AttitudeGovernor(p, cones), SetupError);
  p = paper_params();
  p.epsilon_gamma = 2.0;
  EXPECT_THROW(AttitudeGovernor(p, cones), SetupError);
  p = paper_params();
  const std::vector<ConeConstraint> too_many(kMaxCones + 1, paper_cone());
  EXPECT_THROW(AttitudeGovernor(p, too_many), SetupError);
}

// Set-up errors are of the library's error family: an InputError that maps to exit code 2
// (docs/architecture.md, "Errors"), never a bare std::invalid_argument ("internal error").
TEST(AttitudeGovernor, SetupErrorsAreInputErrorsWithExitCodeTwo) {
  GovernorParams p = paper_params();
  p.gains.kp = -1.0;
  try {
    (void)AttitudeGovernor(p, std::vector<ConeConstraint>{paper_cone()});
    FAIL() << "a negative kp was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.code(), ExitCode::invalid_input);
    EXPECT_NE(std::string(e.what()).find("kp"), std::string::npos) << e.what();
  }
}

TEST(AttitudeGovernor, EvaluateExposesEveryQuantity) {
  const std::vector<ConeConstraint> cones{paper_cone()};
  const AttitudeGovernor gov(paper_params(), cones);
  const Mat3 R = Mat3::Identity();
  const Vec3 w(0.2, 0.3, 0.4);
  const Mat3 R_d = lie::exp(Vec3(0, std::numbers::pi / 2, 0));
  const GovernorOutput out = gov.evaluate(R, w, R, R_d, true);
  EXPECT_NEAR(out.V, 0.35, 1e-15);
  EXPECT_NEAR(out.gamma_d, gov.gamma_d(), 0.0);
  EXPECT_NEAR(out.gamma, std::min(out.gamma_d, out.gamma_g), 0.0);
  EXPECT_LE((out.tau_b + w).norm(), 1e-15);  // R = R_g: τ = −k_d ω
  EXPECT_EQ(out.cone_count, 1);
  EXPECT_NEAR(out.margins[0], pointing_margin(cones[0], R), 0.0);
  EXPECT_NEAR(out.xi_g.norm(), out.gamma - out.V, 1e-12);
  EXPECT_FALSE(gov.trigger_condition(R, w, R));  // Γ − 3V < 0 at t = 0 in the paper's example
  const GovernorOutput held = gov.evaluate(R, w, R, R_d, false);
  EXPECT_EQ(held.xi_g.norm(), 0.0);
  // Mode none: R_g is R_d itself.
  const AttitudeGovernor none(paper_params(GovernorMode::none), cones);
  EXPECT_LE((none.evaluate(R, w, R, R_d, true).R_g - R_d).norm(), 0.0);
}

// The cones and the four modes (pet, continuous, none, robust) on which the lean evaluations are
// compared with evaluate() bit for bit.
std::vector<ConeConstraint> lean_check_cones() {
  return {paper_cone(), keep_in_cone(Vec3(1, 0, 0), Vec3(0, 1, 0), 2.0)};
}
std::vector<GovernorParams> lean_check_variants() {
  GovernorParams robust = paper_params();
  robust.bounded_step = true;
  robust.robust = RobustMargin{};
  robust.robust->epsilon = 0.05;
  robust.robust->delta = 0.1;
  robust.robust->measurement_margin = 0.01;
  robust.robust->max_reference_step = 0.1;
  return {paper_params(GovernorMode::pet), paper_params(GovernorMode::continuous),
          paper_params(GovernorMode::none), robust};
}

// State i of the lean checks of rates(): R_g near R for even i, ω large every third, the
// tie-break held or not.
struct LeanCheckState {
  Mat3 R, R_g, R_d;
  Vec3 w;
  TieBreak tie;
};
LeanCheckState lean_check_state(int i) {
  LeanCheckState st;
  st.R = test::random_rotation();
  st.R_g = i % 2 == 0 ? Mat3(st.R * lie::exp(test::random_vector_in_ball(0.5))) : test::random_rotation();
  st.R_d = test::random_rotation();
  st.w = test::random_vector_in_ball(i % 3 == 0 ? 2.0 : 0.2);
  st.tie = TieBreak{i % 4 == 1, i % 2, i % 8 < 4 ? 1.0 : -1.0};
  return st;
}

// rates() is evaluate()'s τ and ξ bit for bit, in every mode, with the flag up and down, a held
// tie-break, robust margins, states inside and outside {V ≤ Γ}.
TEST(AttitudeGovernor, RatesAreEvaluatesTorqueAndReferenceRateBitForBit) {
  const std::vector<ConeConstraint> cones = lean_check_cones();
  const std::vector<GovernorParams> variants = lean_check_variants();
  int moving = 0;
  for (const GovernorParams& p : variants) {
    const AttitudeGovernor gov(p, cones);
    for (int i = 0; i < 400; ++i) {
      const auto [R, R_g, R_d, w, tie] = lean_check_state(i);
      for (const bool flag : {true, false}) {
        const GovernorOutput full = gov.evaluate(R, w, R_g, R_d, flag, tie);
        const GovernorRates lean = gov.rates(R, w, R_g, R_d, flag, tie);
        for (int k = 0; k < 3; ++k) {
          EXPECT_EQ(lean.tau_b[k], full.tau_b[k]);
          EXPECT_EQ(lean.xi_g[k], full.xi_g[k]);
        }
        moving += full.xi_g.squaredNorm() > 0.0 ? 1 : 0;
      }
    }
  }
  EXPECT_GT(moving, 100);  // both branches of ξ were compared
}

// rates() with a GovernorMemo is evaluate()'s τ and ξ bit for bit whatever the memo holds: the
// figures of this very state (the monitor before the step's first stage), of the same R_g with
// another (R, ω) (a reference held over the stages), of another state, or nothing; figures() with
// a memo is figures() (docs/performance.md, "Shared cone cosines").
TEST(AttitudeGovernor, RatesWithAMemoAreEvaluatesTorqueAndReferenceRateBitForBit) {
  const std::vector<ConeConstraint> cones = lean_check_cones();
  const std::vector<GovernorParams> variants = lean_check_variants();
  int hits = 0;
  for (const GovernorParams& p : variants) {
    const AttitudeGovernor gov(p, cones);
    GovernorMemo memo;
    for (int i = 0; i < 400; ++i) {
      const auto [R, R_g, R_d, w, tie] = lean_check_state(i);
      for (const bool flag : {true, false}) {
        const GovernorOutput full = gov.evaluate(R, w, R_g, R_d, flag, tie);
        const int kind = (i + (flag ? 0 : 1)) % 4;
        if (kind == 0 || kind == 1) {  // this state, or R_g with another (R, ω)
          const GovernorOutput seen = kind == 0 ? gov.figures(R, w, R_g, R_d, flag, tie, memo)
                                                : gov.figures(test::random_rotation(), -w, R_g, R_d, flag, tie, memo);
          if (kind == 0) {
            const GovernorOutput plain = gov.figures(R, w, R_g, R_d, flag, tie);
            EXPECT_EQ(std::memcmp(&seen.V, &plain.V, sizeof(double)), 0);
            EXPECT_EQ(seen.gamma_g, plain.gamma_g);
            EXPECT_EQ(seen.gamma, plain.gamma);
            EXPECT_EQ(seen.tau_b, plain.tau_b);
            ++hits;
          }
        } else if (kind == 2) {
          (void)gov.figures(test::random_rotation(), w, test::random_rotation(), R_d, flag, tie, memo);
        } else {
          memo = GovernorMemo{};
        }
        const GovernorRates lean = gov.rates(R, w, R_g, R_d, flag, tie, memo);
        for (int k = 0; k < 3; ++k) {
          EXPECT_EQ(lean.tau_b[k], full.tau_b[k]);
          EXPECT_EQ(lean.xi_g[k], full.xi_g[k]);
        }
      }
    }
  }
  EXPECT_GT(hits, 100);
}

// figures() is evaluate() without ρ_n and ξ: every other field bit for bit the same
// (docs/performance.md, "Lean core (issue 48, item 2)").
TEST(AttitudeGovernor, FiguresAreEvaluateWithoutTheFieldBitForBit) {
  const std::vector<ConeConstraint> cones = lean_check_cones();
  const std::vector<GovernorParams> variants = lean_check_variants();
  for (const GovernorParams& p : variants) {
    const AttitudeGovernor gov(p, cones);
    for (int i = 0; i < 200; ++i) {
      const Mat3 R = test::random_rotation();
      const Mat3 R_g = test::random_rotation();
      const Mat3 R_d = test::random_rotation();
      const Vec3 w = test::random_vector_in_ball(i % 3 == 0 ? 2.0 : 0.2);
      const TieBreak tie{i % 4 == 1, i % 2, i % 8 < 4 ? 1.0 : -1.0};
      for (const bool flag : {true, false}) {
        const GovernorOutput full = gov.evaluate(R, w, R_g, R_d, flag, tie);
        const GovernorOutput lean = gov.figures(R, w, R_g, R_d, flag, tie);
        EXPECT_TRUE(lean.rho.isZero(0.0));
        EXPECT_TRUE(lean.xi_g.isZero(0.0));
        EXPECT_EQ(lean.tau_b, full.tau_b);
        EXPECT_EQ(lean.R_g, full.R_g);
        EXPECT_EQ(lean.V, full.V);
        EXPECT_EQ(lean.W, full.W);
        EXPECT_EQ(lean.gamma_d, full.gamma_d);
        EXPECT_EQ(lean.gamma_g, full.gamma_g);
        EXPECT_EQ(lean.gamma, full.gamma);
        EXPECT_EQ(lean.trigger, full.trigger);
        EXPECT_EQ(lean.tie_break.active, full.tie_break.active);
        EXPECT_EQ(lean.cone_count, full.cone_count);
        EXPECT_EQ(lean.margins, full.margins);
      }
    }
  }
}

/// A hand-written flight loop: the body is propagated with RK4 under a torque held over each
/// control period (zero-order hold, as on board), the governor is stepped at 100 Hz.
struct LoopResult {
  double max_tau{0.0};
  double min_margin{1.0};
  double max_V_minus_Gamma{-1.0};
  double final_phi{1.0};
  int samples{0};
  bool flag_changed_off_sample{false};
};

LoopResult flight_loop(GovernorMode mode, double duration) {
  const std::vector<ConeConstraint> cones{paper_cone()};
  const GovernorParams p = paper_params(mode);
  AttitudeGovernor gov(p, cones);
  const Mat3 R_d = lie::exp(Vec3(0, std::numbers::pi / 2, 0));
  Mat3 R = Mat3::Identity();
  Vec3 w(0.2, 0.3, 0.4);
  const Mat3 J = p.J;
  const Mat3 J_inv = J.inverse();
  const double dt = 0.01;
  gov.reset(0.0, R);
  LoopResult r;
  bool prev_flag = gov.trigger_flag();
  const auto n = static_cast<int>(std::lround(duration / dt));
  for (int k = 0; k <= n; ++k) {
    const double t = k * dt;
    const GovernorOutput& out = gov.step(t, R, w, R_d);
    r.max_tau = std::max(r.max_tau, out.tau_b.norm());
    r.min_margin = std::min(r.min_margin, out.min_margin());
    r.max_V_minus_Gamma = std::max(r.max_V_minus_Gamma, out.V - out.gamma);
    r.samples += out.sampled ? 1 : 0;
    if (out.trigger != prev_flag && !out.sampled) {
      r.flag_changed_off_sample = true;
    }
    prev_flag = out.trigger;
    // Plant: Ṙ = R ω̂, J ω̇ = (Jω) × ω + τ with τ held (RK4 on ω, exp map for R, 10 substeps).
    const Vec3 tau = out.tau_b;
    for (int s = 0; s < 10; ++s) {
      const double h = dt / 10.0;
      auto f = [&](const Vec3& om) { return Vec3(J_inv * ((J * om).cross(om) + tau)); };
      const Vec3 k1 = f(w);
      const Vec3 k2 = f(w + 0.5 * h * k1);
      const Vec3 k3 = f(w + 0.5 * h * k2);
      const Vec3 k4 = f(w + h * k3);
      const Vec3 w_next = w + h / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4);
      R = R * lie::exp(0.5 * h * (w + w_next));
      w = w_next;
    }
  }
  r.final_phi = lie::phi(R_d.transpose() * R);
  return r;
}

TEST(AttitudeGovernor, FlightLoopWithoutTheSimulatorKeepsConstraintsAndConverges) {
  const LoopResult pet = flight_loop(GovernorMode::pet, 60.0);
  EXPECT_LE(pet.max_tau, 2.5);
  EXPECT_GE(pet.min_margin, 0.0);
  EXPECT_LE(pet.max_V_minus_Gamma, 0.0);
  EXPECT_LT(pet.final_phi, 1e-6);
  EXPECT_EQ(pet.samples, 121);  // t = 0, 0.5, …, 60
  EXPECT_FALSE(pet.flag_changed_off_sample);

  const LoopResult erg = flight_loop(GovernorMode::continuous, 60.0);
  EXPECT_LE(erg.max_tau, 2.5);
  EXPECT_GE(erg.min_margin, 0.0);
  EXPECT_LT(erg.final_phi, 1e-6);

  const LoopResult none = flight_loop(GovernorMode::none, 20.0);
  EXPECT_GT(none.max_tau, 2.5);
  EXPECT_LT(none.min_margin, 0.0);
}

}  // namespace
}  // namespace attiguard::governor
