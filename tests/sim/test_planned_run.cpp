// The `planned` governor mode (docs/pet-erg.md, section 16.2): the slew170 example within 1.3×
// the eigenaxis bang-bang time with every row of its trajectory re-checked, the symmetric Sun
// case, the flight loop with imperfections, and the governed progress against a disturbance
// beyond the one the run was sized for.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "attiguard/core/errors.hpp"
#include "attiguard/governor/planned_governor.hpp"
#include "attiguard/governor/pointing_threshold.hpp"
#include "attiguard/io/row_sink.hpp"
#include "attiguard/lie/quaternion.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/read_pet_erg.hpp"
#include "attiguard/sim/planned_run.hpp"

namespace attiguard::sim::planned_run_test {
namespace {

using lie::Mat3;
using lie::Vec3;

std::string example_text(const std::string& name) {
  std::ifstream in(std::filesystem::path(ATTIGUARD_SOURCE_DIR) / "examples" / name);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// `text` with each `from` replaced by its `to` (each must occur).
std::string edited(std::string text, const std::vector<std::pair<std::string, std::string>>& edits) {
  for (const auto& [from, to] : edits) {
    const auto pos = text.find(from);
    EXPECT_NE(pos, std::string::npos) << from;
    if (pos != std::string::npos) text.replace(pos, from.size(), to);
  }
  return text;
}

PetErgScenario scenario_of(const std::string& text) {
  return scenario::parse_pet_erg(scenario::parse_document(text, "planned.toml"));
}

/// Keeps every row by column name.
class TableSink final : public io::RowSink {
 public:
  void begin(const std::vector<std::string>& columns) override { columns_ = columns; }
  void row(std::span<const double> values) override { rows_.emplace_back(values.begin(), values.end()); }
  [[nodiscard]] double at(std::size_t row, const std::string& column) const {
    const auto it = std::find(columns_.begin(), columns_.end(), column);
    EXPECT_NE(it, columns_.end()) << column;
    return rows_[row][static_cast<std::size_t>(it - columns_.begin())];
  }
  [[nodiscard]] std::size_t size() const { return rows_.size(); }

 private:
  std::vector<std::string> columns_;
  std::vector<std::vector<double>> rows_;
};

/// Every row of the trajectory re-checked from its quaternion and torque: the smallest cone
/// margin a_cᵀ R a_b − cos θ_c and the largest ‖τ‖.
struct RowCheck {
  double smallest_margin{1.0};
  double largest_torque{0.0};
};
RowCheck check_rows(const TableSink& rows, const PetErgScenario& sc) {
  RowCheck c;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const lie::Quat q(rows.at(i, "q_w"), rows.at(i, "q_x"), rows.at(i, "q_y"), rows.at(i, "q_z"));
    const Mat3 R = lie::quat_to_rotation(q.normalized());
    for (const governor::ConeConstraint& cone : sc.cones) {
      c.smallest_margin = std::min(c.smallest_margin, governor::pointing_margin(cone, R));
    }
    const Vec3 tau(rows.at(i, "tau_x"), rows.at(i, "tau_y"), rows.at(i, "tau_z"));
    c.largest_torque = std::max(c.largest_torque, tau.norm());
  }
  return c;
}

// Issue 44's acceptance: the 170° slew with the Sun, Moon and antenna cones converges within
// 1.3× the eigenaxis bang-bang time (the tuned PET-ERG: 3.85×), every cone kept and
// ‖τ‖ ≤ τ_max at every row re-checked from the quaternions and torques, and at every step.
TEST(PlannedRun, TheSlew170ExampleConvergesWithin1p3TheBangBangTimeKeepingEveryConstraint) {
  const PetErgScenario sc = scenario_of(example_text("pet_erg_slew170_planned.toml"));
  TableSink rows;
  const PetErgResult r = record_pet_erg(sc, rows);
  ASSERT_EQ(r.outcome, PetErgOutcome::converged);
  ASSERT_TRUE(r.planned.has_value());
  const double ratio = r.convergence_time / r.eigenaxis_bang_bang_time;
  std::printf("slew170 planned: converged at %.4g s = %.4g x the bang-bang time %.4g s (plan %.4g s)\n",
              r.convergence_time, ratio, r.eigenaxis_bang_bang_time, r.planned->plan.duration);
  EXPECT_LE(ratio, 1.3);
  const RowCheck c = check_rows(rows, sc);
  EXPECT_GE(c.smallest_margin, 0.0);
  EXPECT_LE(c.largest_torque, sc.params.tau_max);
  EXPECT_GE(r.min_pointing_margin, 0.0);
  EXPECT_LE(r.max_torque_norm, sc.params.tau_max);
  // The clock keeps the plan's pace: the plan's interpolants (R, ω cubic, ω̇ the inverse
  // dynamics of the linear torque) are consistent only to the transcription's accuracy, which
  // may cost a choice a small brake, never a hold.
  EXPECT_GE(r.planned->min_rate, 0.99);
  EXPECT_EQ(r.planned->time_held, 0.0);
  EXPECT_LE(r.planned->max_demand_ratio, 1.0);  // the saturation never acted
  EXPECT_EQ(r.planned->saturated_commands, 0);
  std::printf("  %ld of %ld choices inadmissible, min rate %.5g\n", r.planned->inadmissible_samples,
              r.planned->samples, r.planned->min_rate);
  EXPECT_GT(rows.size(), 100u);
}

// The Sun exactly between start and target on the eigenaxis path (the navigation field's saddle
// of docs/pet-erg.md, section 4): the plan goes around the cone and the flight converges.
TEST(PlannedRun, TheSymmetricSunCaseConverges) {
  const std::string text = edited(example_text("pet_erg_symmetric_sun.toml"),
                                  {{"governor = \"pet\"", "governor = \"planned\""},
                                   {"[erg]\nkappa = 1.0\nc_gamma = 3.0\nsampling_period = 0.5                  # T_s [s]\nepsilon = 1e-3\n", ""}});
  const PetErgScenario sc = scenario_of(text);
  const PetErgResult r = simulate_pet_erg(sc);
  EXPECT_EQ(r.outcome, PetErgOutcome::converged);
  EXPECT_GE(r.min_pointing_margin, 0.0);
  EXPECT_LE(r.max_torque_norm, sc.params.tau_max);
  EXPECT_GE(r.planned->plan.path_waypoints, 1);  // around the cone, not through it
}

/// The slew170 example in the flight loop at 10 Hz with the imperfections of `imperfections`.
std::string flight_text(const std::string& imperfections) {
  return edited(example_text("pet_erg_slew170_planned.toml"),
                {{"tau_max = 0.5                          # N m\n",
                  "tau_max = 0.5                          # N m\ncontrol_period = 0.1\n"}}) +
         "\n[imperfections]\n" + imperfections;
}

// The flight loop at 10 Hz with sensor biases and noises, a one-period delay, quantisation and a
// random disturbance (nominal margins: the guarantee does not cover them; robust margins are
// issue 45): with the gains and the headroom derived from the sensors' errors every constraint is
// kept and the slew converges within 1.3× its plan.
TEST(PlannedRun, TheFlightLoopWithImperfectionsKeepsEveryConstraintAndConverges) {
  const PetErgScenario sc = scenario_of(flight_text(
      "disturbance = \"random\"\ndisturbance_bound = 0.005\nattitude_bias = [0.0002, -0.0001, 0.0001]\n"
      "attitude_noise = 0.0001\nrate_bias = [0.00001, 0.0, -0.00001]\nrate_noise = 0.00002\n"
      "delay_periods = 1\ntorque_quantum = 0.0005\nseed = 3\n"));
  const PetErgResult r = simulate_pet_erg(sc);
  ASSERT_EQ(r.outcome, PetErgOutcome::converged);
  EXPECT_GE(r.min_pointing_margin, 0.0);
  EXPECT_LE(r.max_torque_norm, sc.params.tau_max);
  EXPECT_LE(r.convergence_time, 1.3 * r.planned->plan.duration);
  EXPECT_LE(r.planned->max_demand_ratio, 1.0);  // the saturation never acted
  std::printf("flight loop: converged at %.4g s = %.4g x the plan, %ld of %ld choices inadmissible\n",
              r.convergence_time, r.convergence_time / r.planned->plan.duration,
              r.planned->inadmissible_samples, r.planned->samples);
}

/// What a flight of a planned setup did under a constant body torque d_b (RK4 midpoint steps of
/// h with the torque held, the governor stepped at every step, or the clock forced to ṡ = 1).
struct Flown {
  double largest_torque_ratio{0.0};  ///< max ‖τ‖/τ_max of the law
  double smallest_margin{1.0};       ///< min a_cᵀ R a_b − cos θ_c
  double converged_at{-1.0};
  double min_rate{1.0};
  double end_of_plan{-1.0};          ///< when σ reached T_p
};
Flown fly(const PlannedSetup& s, const Vec3& d_b, double h, bool forced, double gain_factor = 1.0) {
  governor::PlannedGovernorParams params = s.params;
  params.gains.k_R *= gain_factor;
  params.gains.k_Omega *= gain_factor;
  governor::PlannedGovernor gov(s.planned.plan, s.run.cones, params);
  const Mat3& J = s.run.params.J;
  const double T = s.planned.plan.duration();
  const Mat3 R_d = s.run.desired.final_attitude();
  Mat3 R = s.run.R0_ib;
  Vec3 w = Vec3::Zero();
  gov.reset(0.0);
  Flown out;
  const long steps = std::lround(4.0 * T / h);
  for (long k = 0; k <= steps; ++k) {
    const double t = static_cast<double>(k) * h;
    Vec3 tau;
    if (forced) {
      tau = control::tracking_torque(J, R, w, gov.progress().reference(std::min(t, T), 1.0),
                                     params.gains);
    } else {
      const governor::PlannedOutput& o = gov.step(t, R, w);
      tau = o.tau_b;
      // The law's demand, before the saturation.
      out.largest_torque_ratio = std::max(out.largest_torque_ratio, o.demand_ratio);
      if (o.sigma < T) out.min_rate = std::min(out.min_rate, o.rate);
      if (o.sigma >= T && out.end_of_plan < 0.0) out.end_of_plan = t;
    }
    out.largest_torque_ratio = std::max(out.largest_torque_ratio, tau.norm() / params.tau_max);
    for (const governor::ConeConstraint& c : s.run.cones) {
      out.smallest_margin = std::min(out.smallest_margin, governor::pointing_margin(c, R));
    }
    if (lie::phi(R_d.transpose() * R) <= s.run.convergence_tolerance) {  // from here to the end
      if (out.converged_at < 0.0) out.converged_at = t;
    } else {
      out.converged_at = -1.0;
    }
    const Vec3 total = tau + d_b;
    const Vec3 a1 = J.ldlt().solve((J * w).cross(w) + total);
    const Vec3 w_mid = w + 0.5 * h * a1;
    const Vec3 a2 = J.ldlt().solve((J * w_mid).cross(w_mid) + total);
    R = R * lie::exp(h * w_mid);
    w = w + h * a2;
  }
  return out;
}

/// The slew170 example at 10 Hz sized for a constant disturbance of 1 % τ_max.
PetErgScenario sized_for_one_percent() {
  return scenario_of(edited(example_text("pet_erg_slew170_planned.toml"),
      {{"tau_max = 0.5                          # N m\n",
        "tau_max = 0.5                          # N m\ncontrol_period = 0.1\n"},
       {"[simulation]", "[imperfections]\ndisturbance = \"constant\"\ndisturbance_bound = 0.005\n"
                         "\n[simulation]"}}));
}

// The governed progress does its job: the slew170 example sized for a constant disturbance of
// 1 % of τ_max (its plan keeps τ_max − d̄ with the derived headroom) meets 10× that disturbance,
// against the plan's initial torque. The governed clock slows (ṡ < 1), every cone and
// ‖τ‖ ≤ τ_max are kept and the slew converges; the same flight with the clock forced to ṡ = 1
// asks for more than τ_max (the test fails if the governor is replaced by ṡ = 1).
TEST(PlannedRun, AgainstTenTimesTheDisturbanceSizedForTheProgressSlowsAndKeepsTheConstraints) {
  const PetErgScenario sc = sized_for_one_percent();
  const PlannedSetup setup = planned_setup(sc);
  const Vec3 tau0 = setup.planned.plan.evaluate(0.0).tau_b;
  const Vec3 d_b = -10.0 * sc.imperfections.disturbance.bound * tau0.normalized();
  const double h = setup.planned.plan.duration() / 4000.0;
  const Flown governed = fly(setup, d_b, h, false);
  const Flown forced = fly(setup, d_b, h, true);
  std::printf("10x disturbance: governed max |tau|/tau_max %.4f, min margin %.4g, min rate %.3g, "
              "plan ended at %.4g s, converged at %.4g s; forced: max |tau|/tau_max %.4f, min margin %.4g\n",
              governed.largest_torque_ratio, governed.smallest_margin, governed.min_rate,
              governed.end_of_plan, governed.converged_at, forced.largest_torque_ratio,
              forced.smallest_margin);
  EXPECT_LE(governed.largest_torque_ratio, 1.0);
  EXPECT_GE(governed.smallest_margin, 0.0);
  EXPECT_LT(governed.min_rate, 1.0);
  EXPECT_GT(governed.converged_at, 0.0);
  EXPECT_TRUE(forced.largest_torque_ratio > 1.0 || forced.smallest_margin < 0.0);
}

// The other half of the same acceptance: the tracking gains halved (the slew170 example sized
// for a constant disturbance of 1 % τ_max meets 5× that): the governed clock slows and keeps
// every constraint and converges; forced to ṡ = 1 the law asks for more than τ_max.
TEST(PlannedRun, WithTheGainsHalvedTheProgressSlowsAndKeepsTheConstraints) {
  const PetErgScenario sc = sized_for_one_percent();
  const PlannedSetup setup = planned_setup(sc);
  const Vec3 tau0 = setup.planned.plan.evaluate(0.0).tau_b;
  const Vec3 d_b = -5.0 * sc.imperfections.disturbance.bound * tau0.normalized();
  const double h = setup.planned.plan.duration() / 4000.0;
  const Flown governed = fly(setup, d_b, h, false, 0.5);
  const Flown forced = fly(setup, d_b, h, true, 0.5);
  std::printf("gains halved, 5x disturbance: governed max demand %.4f, min margin %.4g, min rate %.3g, "
              "converged at %.4g s; forced: max |tau|/tau_max %.4f, min margin %.4g\n",
              governed.largest_torque_ratio, governed.smallest_margin, governed.min_rate,
              governed.converged_at, forced.largest_torque_ratio, forced.smallest_margin);
  EXPECT_LE(governed.largest_torque_ratio, 1.0);
  EXPECT_GE(governed.smallest_margin, 0.0);
  EXPECT_LT(governed.min_rate, 1.0);
  EXPECT_GT(governed.converged_at, 0.0);
  EXPECT_TRUE(forced.largest_torque_ratio > 1.0 || forced.smallest_margin < 0.0);
}

}  // namespace
}  // namespace attiguard::sim::planned_run_test
