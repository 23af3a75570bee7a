// End-to-end tests of the `attiguard` program on the rigid_body kind (docs/scenario-format.md, docs/errors.md).
#include <gtest/gtest.h>

#include <fstream>
#include <ostream>
#include <string>
#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace attiguard::test {
namespace {

TEST(Cli, VersionAndHelp) {
  const CliResult v = run_cli("--version");
  EXPECT_EQ(v.exit_code, 0);
  EXPECT_NE(v.out.find("attiguard"), std::string::npos);
  const CliResult h = run_cli("--help");
  EXPECT_EQ(h.exit_code, 0);
  EXPECT_NE(h.out.find("run"), std::string::npos);
  EXPECT_NE(h.out.find("check"), std::string::npos);
}

TEST(Cli, RunPdScenarioConvergesAndWritesOutputs) {
  const auto out = fresh_dir("pd_run");
  const CliResult r = run_cli("run examples/rigid_body_pd.toml --out '" + out.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string csv = read_file(out / "trajectory.csv");
  ASSERT_FALSE(csv.empty());
  EXPECT_EQ(csv.rfind("t,q_w,q_x,q_y,q_z,omega_x,omega_y,omega_z,tau_x,tau_y,tau_z", 0), 0u);
  const auto summary = nlohmann::json::parse(read_file(out / "summary.json"));
  EXPECT_TRUE(summary.contains("wall_time_s"));
  EXPECT_EQ(summary.at("kind"), "rigid_body");
  EXPECT_EQ(summary.at("law"), "pd");
  // 40 s of PD (kp = 5, kd = 1) from a 90° error: R converges to the reference.
  EXPECT_LT(summary.at("final_attitude_error").get<double>(), 1e-6);
  EXPECT_LT(summary.at("final_orthonormality_error").get<double>(), 1e-12);
  // One row per output instant plus the header.
  EXPECT_EQ(count_lines(csv), summary.at("output_rows").get<long>() + 1);
  std::filesystem::remove_all(out);
}

TEST(Cli, FreeBodyConservesEnergy) {
  const auto out = fresh_dir("free_run");
  const CliResult r = run_cli("run examples/rigid_body_free.toml --out '" + out.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto summary = nlohmann::json::parse(read_file(out / "summary.json"));
  EXPECT_LT(summary.at("max_energy_drift_rel").get<double>(), 1e-7);
  EXPECT_LT(summary.at("max_momentum_drift_rel").get<double>(), 1e-7);
  std::filesystem::remove_all(out);
}

TEST(Cli, PlotWritesPngsOrExplainsWhyNot) {
  const auto out = fresh_dir("pd_plot");
  const CliResult r =
      run_cli("run examples/rigid_body_pd.toml --out '" + out.string() + "' --plot");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const bool have_matplotlib = std::system("/usr/bin/python3 -c 'import matplotlib' 2>/dev/null") == 0;
  if (have_matplotlib) {
    EXPECT_TRUE(std::filesystem::exists(out / "attitude_error.png")) << r.out << r.err;
  } else {
    EXPECT_NE((r.out + r.err).find("no plots"), std::string::npos);
  }
  std::filesystem::remove_all(out);
}

struct BadInput {
  const char* file;
  const char* key;   // key path the message must name
  const char* line;  // ":LINE:" the message must contain
};

// gtest prints the parameter in test listings: show the file, not the pointers' bytes.
void PrintTo(const BadInput& p, std::ostream* os) { *os << p.file; }

class CliBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(CliBadInput, CheckExitsTwoWithOneLineNamingLineAndKey) {
  const BadInput& p = GetParam();
  const CliResult r = run_cli(std::string("check examples/bad/") + p.file);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(p.file), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(p.key), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(p.line), std::string::npos) << r.err;
  // `run` refuses the same file with the same code.
  const auto out = fresh_dir("bad_run");
  EXPECT_EQ(run_cli(std::string("run examples/bad/") + p.file + " --out '" + out.string() + "'")
                .exit_code,
            2);
  std::filesystem::remove_all(out);
}

INSTANTIATE_TEST_SUITE_P(
    RigidBodyBadInputs, CliBadInput,
    ::testing::Values(BadInput{"typo_key.toml", "control.kpp", ":15:"},
                      BadInput{"non_orthonormal.toml", "control.reference", ":17:"},
                      BadInput{"nan_value.toml", "initial.omega_b", ":11:"}),
    [](const ::testing::TestParamInfo<BadInput>& info) {
      std::string name = info.param.file;  // "typo_key.toml" -> "typo_key"
      return name.substr(0, name.find('.'));
    });

TEST(Cli, MissingFileAndBadArgumentsExitTwo) {
  EXPECT_EQ(run_cli("check examples/does_not_exist.toml").exit_code, 2);
  EXPECT_EQ(run_cli("run examples/rigid_body_pd.toml").exit_code, 2);  // --out missing
  EXPECT_EQ(run_cli("frobnicate").exit_code, 2);
}

TEST(Cli, CheckAcceptsTheExamples) {
  for (const char* f : {"examples/rigid_body_pd.toml", "examples/rigid_body_free.toml"}) {
    const CliResult r = run_cli(std::string("check ") + f);
    EXPECT_EQ(r.exit_code, 0) << f << ": " << r.err;
  }
}


// A scenario whose outputs cannot fit in memory (5·10^18 output instants: more than a vector can
// hold, std::length_error before any allocation, also under ASan) is an input error (exit 2)
// saying what was too large, not an "internal error" (app/failure.hpp).
// A run too large to finish (5e18 output rows) is refused before any work, located at
// the key that sets its size (the out-of-memory mapping of app/failure.hpp is tested in
// tests/app/test_failure.cpp).
TEST(Cli, ScenarioTooLargeToRunIsRefusedBeforeAnyWork) {
  const auto dir = fresh_dir("too_large");
  const auto scenario = dir / "huge.toml";
  std::ofstream(scenario) << "kind = \"rigid_body\"\n[body]\ninertia = [1.0, 2.0, 3.0]\n"
                             "[control]\nlaw = \"free\"\n"
                             "[simulation]\nduration = 5e15\noutput_interval = 1e-3\nstep = 1e9\n";
  const CliResult r =
      run_cli("run '" + scenario.string() + "' --out '" + (dir / "out").string() + "'");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("huge.toml:8:19: simulation.output_interval: needs 5e+18 output rows"),
            std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
  EXPECT_EQ(count_lines(r.err), 1) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "trajectory.csv"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace attiguard::test
