// Hold-interval certificate (docs/mission.md): ConReach proves that the PD closed loop (3) towards
// a held R_g keeps the pointing cone (2b) for T_s from a ball around a held state of the PET-ERG
// paper scenario; a four-times-larger ball cannot be proved (exit 4); a partitioned larger set is.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "attiguard/control/pd_so3.hpp"
#include "attiguard/dynamics/rigid_body.hpp"
#include "attiguard/lie/so3.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/read_pet_erg.hpp"
#include "attiguard/scenario/read_reach.hpp"
#include "attiguard/sim/pet_erg_run.hpp"
#include "cli_runner.hpp"

namespace {

const std::filesystem::path kSource{ATTIGUARD_SOURCE_DIR};

}  // namespace

// The centre of the certified ball is the state of examples/pet_erg_paper.toml at t = 5.5 s, the
// start of a hold interval (trigger false), and the reference is the R_g held there.
TEST(HoldCertificate, CentreIsAHeldStateOfThePaperScenario) {
  const auto reach_doc = attiguard::scenario::load_document(kSource / "examples/conreach_hold_certificate.toml");
  const auto reach_sc = attiguard::scenario::parse_reach(reach_doc);
  const auto pet_doc = attiguard::scenario::load_document(kSource / "examples/pet_erg_paper.toml");
  const auto pet_sc = attiguard::scenario::parse_pet_erg(pet_doc);

  bool seen = false;
  attiguard::lie::Mat3 R_at{}, R_g_at{};
  attiguard::lie::Vec3 w_at{};
  bool trigger_at = true;
  (void)attiguard::sim::simulate_pet_erg(
      pet_sc, [&](double t, const attiguard::sim::PetErgState& y, const attiguard::lie::Mat3&,
                  const attiguard::governor::GovernorOutput& out) {
        if (!seen && std::abs(t - 5.5) < 1e-9) {
          seen = true;
          R_at = y.R[0];
          w_at = y.x;
          R_g_at = out.R_g;
          trigger_at = out.trigger;
        }
      });
  ASSERT_TRUE(seen);
  EXPECT_FALSE(trigger_at);
  EXPECT_LT(attiguard::lie::distance(R_at, reach_sc.initial.R0), 1e-6);
  EXPECT_LT((w_at - reach_sc.initial.omega0).norm(), 1e-6);
  // The reach model's vector field is the paper's PD loop (3) towards the R_g held at t = 5.5 s.
  const attiguard::dynamics::RigidBody body(pet_sc.params.J);
  const attiguard::lie::Vec3 expected = body.angular_acceleration(
      w_at, attiguard::control::pd_torque(R_at, w_at, R_g_at, pet_sc.params.gains));
  EXPECT_LT((reach_sc.loop->omega_dot(R_at, w_at) - expected).norm(), 1e-6);
}

#ifdef ATTIGUARD_CLI_PATH

TEST(HoldCertificate, CertificateExampleIsSafe) {
  const auto out = attiguard::test::fresh_dir("hold_certificate_out");
  const auto scenario = attiguard::test::reach_example_for_this_build("conreach_hold_certificate.toml");
  const auto r = attiguard::test::run_cli("reach '" + scenario.string() + "' --out '" + out.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(attiguard::test::read_file(out / "reach.json"));
  EXPECT_EQ(j["verdict"], "safe");
  EXPECT_DOUBLE_EQ(j["horizon"].get<double>(), 0.5);
  EXPECT_EQ(j["soundness"]["inside"].get<long>(), j["soundness"]["samples"].get<long>());
  std::filesystem::remove_all(out);
}

// The example keeps its single ball (`split = false`): cannot_prove, exit 4. Without that line
// the automatic splitting (docs/reach.md, "Automatic splitting") proves the same set safe.
TEST(HoldCertificate, TooLargeBallCannotBeProvedExit4AndTheSplittingProvesIt) {
  const auto out = attiguard::test::fresh_dir("hold_too_large_out");
  const auto scenario = attiguard::test::reach_example_for_this_build("conreach_hold_too_large.toml");
  const auto r = attiguard::test::run_cli("reach '" + scenario.string() + "' --out '" + out.string() + "'");
  EXPECT_EQ(r.exit_code, 4) << r.err;
  EXPECT_NE(r.err.find("cannot be proved"), std::string::npos) << r.err;
  const auto j = nlohmann::json::parse(attiguard::test::read_file(out / "reach.json"));
  EXPECT_EQ(j["verdict"], "cannot_prove");
  EXPECT_EQ(j["cells"].get<long>(), 1);

  // The splitting proves it in about 30 s of SDPs in Release; the sanitized build stops here
  // (ReachAutoSplit and the corpus dozen cover the splitting there).
  if (attiguard::test::kSanitizedWorkDivisor > 1) return;
  std::string text = attiguard::test::read_file(kSource / scenario);
  const std::size_t at = text.rfind("split = false");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 13, "split = true\nmax_seconds = 3600.0");  // the cell-step budget decides
  const auto split = out / "split.toml";
  std::ofstream(split) << text;
  const auto s = attiguard::test::run_cli("reach '" + split.string() + "' --out '" + (out / "s").string() + "'");
  ASSERT_EQ(s.exit_code, 0) << s.err;
  const auto js = nlohmann::json::parse(attiguard::test::read_file(out / "s" / "reach.json"));
  EXPECT_EQ(js["verdict"], "safe");
  EXPECT_GT(js["cells"].get<long>(), 1);
  EXPECT_GE(js["partition"]["cells_split"].get<long>(), 1);
  EXPECT_EQ(js["partition"]["leaves_unproved"].get<long>(), 0);
  EXPECT_EQ(js["soundness"]["inside"].get<long>(), js["soundness"]["samples"].get<long>());
  EXPECT_LE(js["adversarial"]["worst_ratio"].get<double>(), 1.0);
  std::filesystem::remove_all(out);
}

// Partitioning proves a set that one ball cannot (contraction-reachability paper, Sec. 4.1).
TEST(HoldCertificate, PartitionedSetIsSafeWhereOneBallCannotBeProved) {
  const auto doc = attiguard::scenario::load_document(kSource / "examples/conreach_hold_partitioned.toml");
  const auto sc = attiguard::scenario::parse_reach(doc);
  ASSERT_EQ(sc.attitude_cells, 3);
  const auto out = attiguard::test::fresh_dir("hold_partitioned_out");
  const auto scenario = attiguard::test::reach_example_for_this_build("conreach_hold_partitioned.toml");
  const auto r = attiguard::test::run_cli("reach '" + scenario.string() + "' --out '" + out.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(attiguard::test::read_file(out / "reach.json"));
  EXPECT_EQ(j["verdict"], "safe");
  EXPECT_EQ(j["cells"].get<long>(), 27);
  EXPECT_EQ(j["soundness"]["inside"].get<long>(), j["soundness"]["samples"].get<long>());

  // The same set as one cell: the example without its [partition] table (its last table).
  std::string text = attiguard::test::read_file(kSource / scenario);
  text = text.substr(0, text.find("[partition]")) + "[partition]\nsplit = false\n";
  const auto one = out / "one_ball.toml";
  std::ofstream(one) << text;
  const auto r1 = attiguard::test::run_cli("reach '" + one.string() + "' --out '" +
                                           (out / "one").string() + "'");
  EXPECT_EQ(r1.exit_code, 4) << r1.err;
  std::filesystem::remove_all(out);
}

// Issue 15: with the coupled metric (the default for the PD loop) one ball of 3.5× the radii of
// the certificate example (0.07 rad, 0.07 rad/s instead of 0.02, 0.02) is proved safe; the
// product metric's largest is 0.06 (docs/reach.md, "Coupled metrics"), it fails at 0.07.
TEST(HoldCertificate, CoupledMetricProvesALargerSingleBallThanTheProductMetric) {
  std::string text = attiguard::test::read_file(kSource / "examples/conreach_hold_certificate.toml");
  auto replace = [&text](const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
  };
  replace("attitude_radius = 0.02 ", "attitude_radius = 0.07 ");
  replace("omega_radius = 0.02 ", "omega_radius = 0.07 ");
  replace("samples = 2000", "samples = " + std::to_string(attiguard::test::for_this_build(1000, 100)));
  const auto out = attiguard::test::fresh_dir("hold_certificate_2x_out");
  const auto twice = out / "twice.toml";
  std::ofstream(twice) << text;
  const auto r = attiguard::test::run_cli("reach '" + twice.string() + "' --out '" + (out / "c").string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(attiguard::test::read_file(out / "c" / "reach.json"));
  EXPECT_EQ(j["metric"], "coupled");
  EXPECT_EQ(j["verdict"], "safe");
  EXPECT_DOUBLE_EQ(j["initial"]["attitude_radius"].get<double>(), 0.07);
  EXPECT_EQ(j["soundness"]["inside"].get<long>(), j["soundness"]["samples"].get<long>());
  EXPECT_LT(j["adversarial"]["worst_ratio"].get<double>(), 1.0);
  for (const auto& st : j["steps"]) EXPECT_EQ(st["rigour"], "rigorous");
  replace("[reach]\n", "[reach]\nmetric = \"product\"\n");
  std::ofstream(twice) << text << "\n[partition]\nsplit = false\n";
  const auto p = attiguard::test::run_cli("reach '" + twice.string() + "' --out '" + (out / "p").string() + "'");
  EXPECT_EQ(p.exit_code, 4) << p.err;
  std::filesystem::remove_all(out);
}

#endif
