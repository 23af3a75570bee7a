// app/tune_search: the gain search of a pet_erg scenario (docs/pet-erg.md, section "Tuning").

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <vector>
#include <filesystem>
#include <string>
#include <unistd.h>

#include "attiguard/app/tune_search.hpp"
#include "attiguard/core/errors.hpp"
#include "attiguard/scenario/dispersion.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/document_edit.hpp"
#include "attiguard/scenario/read_pet_erg.hpp"
#include "attiguard/governor/default_gains.hpp"
#include "attiguard/sim/planned_run.hpp"

namespace attiguard::app {
namespace {

std::filesystem::path tune_scratch(const std::string& name) {
  return std::filesystem::temp_directory_path() /
         ("attiguard_tune_" + name + "_" + std::to_string(::getpid()));
}

scenario::Document source_file(const std::string& relative) {
  const scenario::Document d = scenario::load_document(std::string(ATTIGUARD_SOURCE_DIR) + "/" + relative);
  return d.has_top_level("dispersions") ? scenario::nominal_document(d) : d;
}

TuneSettings settings(std::vector<TuneParameter> p, long budget, int threads, const std::string& name) {
  TuneSettings s;
  s.parameters = std::move(p);
  s.budget = budget;
  s.threads = threads;
  s.seed = 7;
  s.scratch = tune_scratch(name);
  return s;
}

// The paper scenario (slew of 90 deg, one keep-in cone; gains around the paper's): the search
// finds admissible points,
// the best is the fastest of them, and its values are inside the box.
TEST(TuneSearch, BestIsTheFastestAdmissiblePointInsideTheBox) {
  const scenario::Document doc = source_file("examples/pet_erg_paper.toml");
  const TuneSettings s =
      settings({{"control.kp", 2.0, 10.0}, {"control.kd", 0.5, 3.0}, {"erg.kappa", 0.5, 5.0}}, 16, 2, "best");
  const TuneResult r = tune_search(doc, s);
  ASSERT_EQ(r.points.size(), 16u);
  ASSERT_TRUE(r.best.has_value());
  const TunePoint& b = r.points[*r.best];
  EXPECT_TRUE(b.admissible());
  for (const TunePoint& p : r.points) {
    if (p.admissible()) {
      EXPECT_LE(*b.convergence_time, *p.convergence_time);
    }
    for (std::size_t d = 0; d < s.parameters.size(); ++d) {
      EXPECT_GE(p.values[d], s.parameters[d].min);
      EXPECT_LE(p.values[d], s.parameters[d].max);
    }
  }
  ASSERT_TRUE(r.eigenaxis_bang_bang_time.has_value());
  EXPECT_NEAR(*b.ratio, *b.convergence_time / *r.eigenaxis_bang_bang_time, 1e-9);
  // The paper's own gains (kp 5, kd 1, kappa 1) are the nominal point: converged at 30.55 s.
  EXPECT_EQ(r.nominal.outcome, "converged");
  const nlohmann::json j = tune_json(s, r);
  EXPECT_EQ(j["outcome"], "found");
  EXPECT_EQ(j["points"].size(), 16u);
  EXPECT_DOUBLE_EQ(j["convergence_time"].get<double>(), *b.convergence_time);
}

// Same seed: the same points and results whatever the thread count.
TEST(TuneSearch, DeterministicForASeedWhateverTheThreadCount) {
  const scenario::Document doc = source_file("examples/pet_erg_paper.toml");
  const auto p = default_tune_parameters(doc);
  const nlohmann::json one = tune_json(settings(p, 12, 1, "det1"), tune_search(doc, settings(p, 12, 1, "det1")));
  const nlohmann::json two = tune_json(settings(p, 12, 2, "det2"), tune_search(doc, settings(p, 12, 2, "det2")));
  EXPECT_EQ(one.dump(), two.dump());
  // More workers than the batch of 4 (the batch is not tied to them; under MPI the workers are
  // ranks x threads: tests/cli/tune_mpi_equal.cmake).
  const nlohmann::json five = tune_json(settings(p, 12, 5, "det5"), tune_search(doc, settings(p, 12, 5, "det5")));
  EXPECT_EQ(one.dump(), five.dump());
  TuneSettings other = settings(p, 12, 1, "det3");
  other.seed = 8;
  EXPECT_NE(tune_json(other, tune_search(doc, other))["points"].dump(), one["points"].dump());
}

// A space that holds only stalling gains (two keep-out cones whose repulsive bands overlap
// across the path, docs/pet-erg.md "Outcomes"): no admissible point, said so.
TEST(TuneSearch, OnlyStallingGainsReportNoConvergedPoint) {
  const scenario::Document doc = source_file("tests/data/campaign/pet_erg_stalling.toml");
  const TuneSettings s = settings({{"control.kp", 4.0, 6.0}, {"control.kd", 0.8, 1.2}, {"erg.kappa", 0.8, 1.2}},
                                  6, 2, "stall");
  const TuneResult r = tune_search(doc, s);
  EXPECT_FALSE(r.best.has_value());
  ASSERT_EQ(r.points.size(), 6u);
  for (const TunePoint& p : r.points) {
    EXPECT_EQ(p.status, "ok");
    EXPECT_EQ(p.outcome, "stalled");
    EXPECT_FALSE(p.admissible());
  }
  const nlohmann::json j = tune_json(s, r);
  EXPECT_EQ(j["outcome"], "none_converged");
  EXPECT_EQ(j["outcome_reason"], "none of the 6 evaluated points converged with every constraint kept");
  EXPECT_TRUE(j["best"].is_null());
}

// A set stop flag (the interruption flag, docs/pet-erg.md section 15 "Interruption") ends the
// search at once: no candidate is evaluated after it, the result says it was stopped, and
// tune.json's outcome is "interrupted" with the runs done against the budget (issue 49).
TEST(TuneSearch, ASetStopFlagEndsTheSearchWithThePointsSoFar) {
  const scenario::Document doc = source_file("examples/pet_erg_paper.toml");
  std::atomic<bool> stop{true};
  TuneSettings s = settings({{"control.kp", 2.0, 10.0}}, 100000, 2, "stop");
  s.stop = &stop;
  const TuneResult r = tune_search(doc, s);
  EXPECT_TRUE(r.stopped);
  EXPECT_TRUE(r.points.empty());
  EXPECT_EQ(r.nominal.status, "stopped");
  const nlohmann::json j = tune_json(s, r);
  EXPECT_EQ(j["outcome"], "interrupted");
  EXPECT_EQ(j["stopped"], true);
  EXPECT_EQ(j["outcome_reason"], "the search was stopped after 0 of 100000 runs; no admissible point so far");
  // Unset: the search runs its budget and says nothing of a stop.
  stop = false;
  s.budget = 4;
  const TuneResult full = tune_search(doc, s);
  EXPECT_FALSE(full.stopped);
  EXPECT_EQ(full.points.size(), 4u);
  EXPECT_FALSE(tune_json(s, full).contains("stopped"));
}

// Gains whose Gamma_d over/underflows are refused by the parser, not simulated.
TEST(TuneSearch, GainsWhoseGammaDOverflowsAreRejectedNotRun) {
  const scenario::Document doc = source_file("examples/pet_erg_paper.toml");
  const TuneSettings s = settings({{"control.kp", 1e290, 1e300}}, 4, 1, "overflow");
  const TuneResult r = tune_search(doc, s);
  EXPECT_FALSE(r.best.has_value());
  for (const TunePoint& p : r.points) {
    EXPECT_EQ(p.status, "rejected");
    EXPECT_NE(p.reason.find("over/underflow Gamma_d"), std::string::npos) << p.reason;
  }
}

TEST(TuneSearch, CandidateSetsTheKeysAndAddsAnAbsentOne) {
  const scenario::Document doc = source_file("examples/pet_erg_paper.toml");
  const scenario::Document c = tune_candidate(doc, {{"control.kp", 1, 1}, {"control.control_period", 1, 1}},
                                              {2.5, 0.1});
  EXPECT_EQ(scenario::number_at(c, "control.kp"), 2.5);
  EXPECT_EQ(scenario::number_at(c, "control.control_period"), 0.1);
  EXPECT_EQ(scenario::number_at(doc, "control.kp"), 5.0);  // the nominal is not changed
}

// The default space is centred on the parsed values (the parser's defaults for absent keys).
TEST(TuneSearch, DefaultSpaceIsCentredOnTheCraftsDerivedValuesAndScaledByThem) {
  // the paper's gains in the file do not move the space: it is the craft's (docs/pet-erg.md 15)
  const scenario::Document doc = source_file("tests/data/campaign/pet_erg_stalling.toml");
  const auto p = default_tune_parameters(doc);
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p[0].key, "control.kp");
  EXPECT_EQ(p[1].key, "control.kd");
  EXPECT_EQ(p[2].key, "erg.sampling_period");
  const sim::PetErgScenario sc = scenario::parse_pet_erg(doc);
  const governor::DerivedGovernorValues d = governor::derive_governor_values(sim::craft_scales(sc), {});
  const TuneSpaceConstants k;
  EXPECT_NEAR(std::sqrt(p[0].min * p[0].max), d.kp, 1e-12 * d.kp);
  EXPECT_NEAR(p[0].max / p[0].min, k.stiffness * k.stiffness, 1e-9);
  EXPECT_NEAR(std::sqrt(p[1].min * p[1].max), d.kd, 1e-12 * d.kd);
  EXPECT_NEAR(std::sqrt(p[2].min * p[2].max), d.Ts, 1e-12 * d.Ts);
  EXPECT_NE(d.kp, 5.0);
  // 10^3 times the torque: k_p ∝ τ, T_s ∝ 1/√τ (the inertia's scaling: DefaultGains tests)
  scenario::Document strong = doc;
  scenario::set_number(strong, "control.tau_max", 2.5e3);
  const auto q = default_tune_parameters(strong);
  EXPECT_NEAR(q[0].min / p[0].min, 1e3, 1e-9);
  EXPECT_NEAR(q[2].min / p[2].min, 1.0 / std::sqrt(1e3), 1e-9);
}

// governor = "planned" (docs/pet-erg.md, section 16.2): the tracking gains and the plan's
// headroom and cone margin, centred on what the planned mode derives from the craft (the file's
// values set aside) and scaled like the craft: a weaker twin (
// τ_max × 10⁻³: the slew 31.6× slower) gets gains × 10⁻³, the same headroom and margin. A short search
// finds an admissible point within 1.3× the eigenaxis bang-bang time.
TEST(TuneSearch, ThePlannedModeSearchesItsGainsHeadroomAndMarginAroundItsDerivedValues) {
  const scenario::Document doc = source_file("examples/pet_erg_slew170_planned.toml");
  const auto p = default_tune_parameters(doc);
  ASSERT_EQ(p.size(), 4u);
  EXPECT_EQ(p[0].key, "control.kp");
  EXPECT_EQ(p[1].key, "control.kd");
  EXPECT_EQ(p[2].key, "plan.torque_headroom");
  EXPECT_EQ(p[3].key, "plan.cone_margin_deg");
  const sim::PlannedFigures f = sim::planned_setup(scenario::parse_pet_erg(doc)).figures;
  EXPECT_NEAR(std::sqrt(p[0].min * p[0].max), f.gains.k_R, 1e-12 * f.gains.k_R);
  EXPECT_NEAR(std::sqrt(p[1].min * p[1].max), f.gains.k_Omega, 1e-12 * f.gains.k_Omega);
  scenario::Document small = doc;
  scenario::set_number(small, "control.tau_max", 0.5e-3);
  const auto q = default_tune_parameters(small);
  EXPECT_NEAR(q[0].min / p[0].min, 1e-3, 1e-12);  // k_R = J_max ω_n², ω_n ∝ 1/T_bb ∝ √τ
  EXPECT_NEAR(q[2].min, p[2].min, 1e-12);         // the headroom and the margin: dimensionless
  EXPECT_NEAR(q[3].min, p[3].min, 1e-9 * p[3].min);
  const TuneResult r = tune_search(doc, settings(p, 12, 1, "planned"));
  ASSERT_TRUE(r.best.has_value());
  ASSERT_TRUE(r.eigenaxis_bang_bang_time.has_value());
  EXPECT_LE(*r.points[*r.best].convergence_time, 1.3 * *r.eigenaxis_bang_bang_time);
}

TEST(TuneSearch, BestOnABoundIsReported) {
  const std::vector<TuneParameter> space{{"control.kp", 1.0, 100.0}, {"control.kd", 1.0, 100.0}};
  EXPECT_TRUE(keys_on_bound(space, {10.0, 10.0}).empty());
  EXPECT_EQ(keys_on_bound(space, {1.05, 10.0}), std::vector<std::string>{"control.kp"});
  EXPECT_EQ(keys_on_bound(space, {10.0, 99.0}), std::vector<std::string>{"control.kd"});
}

TEST(TuneSearch, BadRangesAndSpacesAreInputErrors) {
  EXPECT_EQ(parse_tune_range("control.kp=0.5:20").min, 0.5);
  EXPECT_EQ(parse_tune_range("control.kp=0.5:20").max, 20.0);
  for (const char* bad : {"control.kp", "control.kp=1", "=1:2", "control.kp=0:2", "control.kp=3:2",
                          "control.kp=1:x", "control.kp=-1:2", "control.kp=1:inf"}) {
    EXPECT_THROW((void)parse_tune_range(bad), InputError) << bad;
  }
  const scenario::Document doc = source_file("examples/pet_erg_paper.toml");
  EXPECT_THROW((void)tune_search(doc, settings({{"control.kp", 1, 2}}, 3, 1, "b1")), InputError);
  EXPECT_THROW((void)tune_search(doc, settings({}, 8, 1, "b2")), InputError);
  EXPECT_THROW((void)tune_search(doc, settings({{"nosuch.table.kp", 1, 2}}, 8, 1, "b3")), InputError);
  EXPECT_THROW((void)default_tune_parameters(source_file("examples/rigid_body_pd.toml")), InputError);
}

}  // namespace
}  // namespace attiguard::app
