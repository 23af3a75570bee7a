/// End-to-end tests of the `attiguard` program, independent of any scenario kind: exit codes, the
/// one-line error contract and the graceful degradation of `--plot` (docs/conventions.md,
/// "Exit codes"). Kind-specific runs are in test_cli_rigid_body.cpp.
#ifdef ATTIGUARD_CLI_PATH

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>

#include "attiguard/core/version.hpp"
#include "attiguard/app/kinds.hpp"

namespace fs = std::filesystem;

namespace {

struct CliResult {
  int exit_code{-1};
  std::string out;
  std::string err;
};

/// A fresh scratch directory per test (tests run in parallel processes under ctest).
fs::path scratch_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::temp_directory_path() / "attiguard_cli_tests" /
                       (std::string(info->test_suite_name()) + "." + info->name());
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string read_file(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

void write_file(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

/// Single-quotes a string for /bin/sh.
std::string quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

/// Runs `[env] attiguard ARGS` through /bin/sh in `dir`, capturing stdout and stderr.
CliResult run_cli(const fs::path& dir, const std::string& args, const std::string& env = "") {
  const std::string cmd = "cd " + quoted(dir.string()) + " && " + env + " " +
                          quoted(ATTIGUARD_CLI_PATH) + " " + args + " >stdout.txt 2>stderr.txt";
  const int status = std::system(cmd.c_str());
  CliResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = read_file(dir / "stdout.txt");
  r.err = read_file(dir / "stderr.txt");
  return r;
}

std::size_t count_lines(const std::string& s) {
  std::size_t n = 0;
  for (char c : s) n += (c == '\n') ? 1 : 0;
  return n;
}

/// The error contract: exactly one stderr line "attiguard: error: …".
void expect_one_error_line(const CliResult& r) {
  EXPECT_EQ(count_lines(r.err), 1u) << r.err;
  EXPECT_EQ(r.err.rfind("attiguard: error: ", 0), 0u) << r.err;
}

fs::path example(const char* name) { return fs::path(ATTIGUARD_SOURCE_DIR) / "examples" / name; }

}  // namespace

TEST(CliContract, VersionPrintsTheProjectVersion) {
  const auto r = run_cli(scratch_dir(), "--version");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.out, std::string("attiguard ") + attiguard::version_string + "\n");
  EXPECT_TRUE(r.err.empty());
}

TEST(CliContract, HelpListsEveryScenarioKind) {
  const auto r = run_cli(scratch_dir(), "--help");
  EXPECT_EQ(r.exit_code, 0);
  ASSERT_FALSE(attiguard::app::kinds().empty());
  for (const auto& kind : attiguard::app::kinds()) {
    EXPECT_NE(r.out.find(std::string(kind.name)), std::string::npos) << kind.name;
    EXPECT_NE(r.out.find(std::string(kind.description)), std::string::npos) << kind.name;
  }
  EXPECT_NE(r.out.find("run"), std::string::npos);
  EXPECT_NE(r.out.find("check"), std::string::npos);
}

TEST(CliContract, BadArgumentsExitTwoWithOneLine) {
  const fs::path dir = scratch_dir();
  for (const char* args : {"", "--bogus", "frobnicate", "run", "run x.toml", "run x.toml --out",
                           "check", "check a.toml b.toml", "run x.toml --out o --plot=maybe"}) {
    SCOPED_TRACE(args);
    const auto r = run_cli(dir, args);
    EXPECT_EQ(r.exit_code, 2);
    expect_one_error_line(r);
  }
}

TEST(CliContract, UnknownSubcommandListsTheSubcommands) {
  const auto r = run_cli(scratch_dir(), "frobnicate");
  EXPECT_EQ(r.exit_code, 2);
  expect_one_error_line(r);
  EXPECT_NE(r.err.find("unknown subcommand 'frobnicate' (subcommands: run, check, reach, plan, campaign"),
            std::string::npos) << r.err;
}

// --seed is an unsigned 64-bit integer: a sign, a value past 2^64 − 1 or trailing characters are
// refused (they used to wrap or clamp to 2^64 − 1).
TEST(CliContract, SeedOutsideUnsigned64BitsIsInvalidInput) {
  const fs::path dir = scratch_dir();
  const std::string file = quoted(example("pet_erg_campaign.toml").string());
  for (const std::string seed : {"-1", "18446744073709551616", "12x", "+3"}) {
    SCOPED_TRACE(seed);
    const auto r = run_cli(dir, "campaign " + file + " --runs 1 --out o --seed=" + seed);
    EXPECT_EQ(r.exit_code, 2);
    expect_one_error_line(r);
    EXPECT_NE(r.err.find("--seed: "), std::string::npos) << r.err;
  }
  EXPECT_EQ(run_cli(dir, "campaign " + file + " --runs 1 --out o --seed 18446744073709551615").exit_code, 0);
}

TEST(CliContract, RunOnACampaignScenarioPointsToAttiguardCampaign) {
  const auto r = run_cli(scratch_dir(), "run " + quoted(example("pet_erg_campaign.toml").string()) + " --out o");
  EXPECT_EQ(r.exit_code, 2);
  expect_one_error_line(r);
  EXPECT_NE(r.err.find("a campaign scenario ([dispersions]): run it with `attiguard campaign"),
            std::string::npos) << r.err;
}

// A device that never ends, or a huge file, is refused after 16 MiB instead of filling memory.
TEST(CliContract, EndlessOrHugeScenarioFileIsRefused) {
  const auto r = run_cli(scratch_dir(), "check /dev/zero");
  EXPECT_EQ(r.exit_code, 2);
  expect_one_error_line(r);
  EXPECT_NE(r.err.find("/dev/zero: cannot read scenario file (larger than 16 MiB"), std::string::npos) << r.err;
}

// Values that parse but cannot be computed with (an angle of 1e300 rad), or that would make a
// run that never finishes or fills the disk (1e-20 s steps, 1e-6 s output intervals, 1e-300 s
// governor periods), are refused by `check` at their key, with the predicted count.
TEST(CliContract, UncomputableOrEndlessValuesAreRefusedAtTheirKey) {
  const fs::path dir = scratch_dir();
  const std::string paper = read_file(example("pet_erg_paper.toml"));
  const struct {
    const char* from;
    const char* to;
    const char* expected;
  } cases[] = {
      {"angle_deg = 90.0 }", "angle_deg = 1e300 }", "desired.attitude.angle_deg: 1e+300 deg is beyond the usable range"},
      {"step = 0.01", "step = 1e-20", "simulation.step: needs 6e+21 integrator steps over the duration 60 s"},
      {"step = 0.01", "step = 1e-7", "simulation.step: needs 6e+08 integrator steps"},
      {"output_interval = 0.01", "output_interval = 1e-6", "simulation.output_interval: needs 6e+07 output rows"},
      {"sampling_period = 0.5", "sampling_period = 1e-300", "erg.sampling_period: needs 6e+301 governor samples"},
      {"duration = 60.0", "duration = 1e300", "simulation.step: needs 1e+302 integrator steps"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.to);
    std::string text = paper;
    const auto at = text.find(c.from);
    ASSERT_NE(at, std::string::npos);
    text.replace(at, std::string(c.from).size(), c.to);
    write_file(dir / "edited.toml", text);
    const auto r = run_cli(dir, "check edited.toml");
    EXPECT_EQ(r.exit_code, 2);
    expect_one_error_line(r);
    EXPECT_NE(r.err.find(c.expected), std::string::npos) << r.err;
  }
  std::string reach = read_file(example("conreach_paper.toml"));
  reach.replace(reach.find("integrator_step = 0.001"), 23, "integrator_step = 1e-100");
  write_file(dir / "reach.toml", reach);
  const auto r = run_cli(dir, "check reach.toml");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("reach.integrator_step: needs 4e+100 integrator steps of the nominal"),
            std::string::npos) << r.err;
}

// A run that fails numerically leaves trajectory.csv.partial (its rows up to the failure) and no
// trajectory.csv or summary.json — not even those of an earlier run in the same folder.
TEST(CliContract, FailedRunLeavesOnlyAPartialTrajectory) {
  const fs::path dir = scratch_dir();
  const std::string pd = read_file(example("rigid_body_pd.toml"));
  write_file(dir / "good.toml", pd);
  ASSERT_EQ(run_cli(dir, "run good.toml --out out").exit_code, 0);
  ASSERT_TRUE(fs::exists(dir / "out/trajectory.csv"));
  ASSERT_TRUE(fs::exists(dir / "out/summary.json"));
  // k_d/J = 3000 1/s with a 0.05 s step: RKMK4 is unstable and the state overflows.
  std::string bad = pd;
  bad.replace(bad.find("kd = 1.0"), 8, "kd = 3000.0");
  bad.replace(bad.find("step = 0.01"), 11, "step = 0.05");
  write_file(dir / "bad.toml", bad);
  const auto r = run_cli(dir, "run bad.toml --out out");
  EXPECT_EQ(r.exit_code, 3) << r.err;
  expect_one_error_line(r);
  EXPECT_FALSE(fs::exists(dir / "out/trajectory.csv"));
  EXPECT_FALSE(fs::exists(dir / "out/summary.json"));
  ASSERT_TRUE(fs::exists(dir / "out/trajectory.csv.partial"));
  EXPECT_EQ(read_file(dir / "out/trajectory.csv.partial").rfind("t,", 0), 0u);
}

// --runs is bounded before any work (10^10 runs used to grow to 2.1 GB, then bad_alloc);
// --max-runs raises the limit, and the limit flags refuse nonsense.
TEST(CliContract, CampaignRunsBeyondTheLimitAreRefusedUntilRaised) {
  const fs::path dir = scratch_dir();
  const std::string file = quoted(example("pet_erg_campaign.toml").string());
  const auto r = run_cli(dir, "campaign " + file + " --runs 10000000000 --out o");
  EXPECT_EQ(r.exit_code, 2);
  expect_one_error_line(r);
  EXPECT_NE(r.err.find("--runs: 10000000000 runs are more than the limit 1e+06"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("raise the limit with --max-runs N"), std::string::npos) << r.err;
  EXPECT_EQ(run_cli(dir, "campaign " + file + " --runs 3 --max-runs 2 --out o").exit_code, 2);
  EXPECT_EQ(run_cli(dir, "campaign " + file + " --runs 2 --max-runs 2 --out o").exit_code, 0);
  for (const char* bad : {"0", "-5", "nan", "1e400", "x"}) {
    SCOPED_TRACE(bad);
    const auto b = run_cli(dir, std::string("check ") + file + " --max-steps " + bad);
    EXPECT_EQ(b.exit_code, 2);
    expect_one_error_line(b);
    EXPECT_NE(b.err.find("must be a number >= 1"), std::string::npos) << b.err;
  }
}

// The work limits have flags: a scenario refused for its step count passes with --max-steps.
TEST(CliContract, MaxStepsRaisesTheStepLimit) {
  const fs::path dir = scratch_dir();
  std::string text = read_file(example("pet_erg_paper.toml"));
  text.replace(text.find("step = 0.01"), 11, "step = 1e-7");
  write_file(dir / "fine.toml", text);
  const auto refused = run_cli(dir, "check fine.toml");
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("at most 1e+08, or raise the limit with --max-steps N"), std::string::npos)
      << refused.err;
  EXPECT_EQ(run_cli(dir, "check fine.toml --max-steps 1e9").exit_code, 0);
}

// A reach partition of 50 x 50 cells per axis is refused at once (it used to run 48 s, then
// bad_alloc); --max-cells raises the limit.
TEST(CliContract, ReachPartitionBeyondTheCellLimitIsRefusedAtOnce) {
  const fs::path dir = scratch_dir();
  std::string text = read_file(example("conreach_hold_partitioned.toml"));
  text.replace(text.find("attitude_cells = 3"), 18, "attitude_cells = 50");
  text.replace(text.find("omega_cells = 1"), 15, "omega_cells = 50");
  write_file(dir / "cells.toml", text);
  const auto r = run_cli(dir, "reach cells.toml --out o");
  EXPECT_EQ(r.exit_code, 2);
  expect_one_error_line(r);
  EXPECT_NE(r.err.find("partition.omega_cells: attitude_cells = 50 and omega_cells = 50 make up to "
                       "1.5625e+10 cells"), std::string::npos) << r.err;
  EXPECT_EQ(run_cli(dir, "check cells.toml --max-cells 1e12").exit_code, 0);
}

// A diverging run names the key most likely responsible, located, with a hint (it used to say
// only "integrator: non-finite state at t = ... (divergence)").
TEST(CliContract, DivergenceNamesTheLikelyKeyWithAHint) {
  const fs::path dir = scratch_dir();
  std::string stiff = read_file(example("rigid_body_pd.toml"));
  stiff.replace(stiff.find("inertia = [1.0, 2.0, 3.0]"), 25, "inertia = [1e-3, 1e3, 1e3]");
  stiff.replace(stiff.find("step = 0.01"), 11, "step = 0.05");
  write_file(dir / "stiff.toml", stiff);
  const auto s = run_cli(dir, "run stiff.toml --out o");
  EXPECT_EQ(s.exit_code, 3);
  expect_one_error_line(s);
  EXPECT_NE(s.err.find("(divergence); likely stiff.toml:25:8: simulation.step: 0.05 s is above the "
                       "stability limit ~ 2/lambda_max = 0.00201 s of this inertia and these gains "
                       "(lambda_max ~ 995 1/s): use integrator = \"rkmk_dp54\" or step <= 0.00201"),
            std::string::npos) << s.err;
  // The hint's advice works: rkmk_dp54 runs it.
  stiff.replace(stiff.find("integrator = \"rkmk4\""), 20, "integrator = \"rkmk_dp54\"");
  write_file(dir / "stiff_dp.toml", stiff);
  EXPECT_EQ(run_cli(dir, "run stiff_dp.toml --out o").exit_code, 0);

  std::string kappa = read_file(example("pet_erg_paper.toml"));
  kappa.replace(kappa.find("kappa = 1.0"), 11, "kappa = 1e300");
  write_file(dir / "kappa.toml", kappa);
  const auto k = run_cli(dir, "run kappa.toml --out o");
  EXPECT_EQ(k.exit_code, 3);
  expect_one_error_line(k);
  EXPECT_NE(k.err.find("likely kappa.toml:28:9: erg.kappa: 1e+300 turns the reference at up to "
                       "kappa Gamma_d = 5.408e+299 rad/s"), std::string::npos) << k.err;
}

// An inertia of 1e300 is an input error at its key, not a divergence.
TEST(CliContract, HugeInertiaIsAnInputError) {
  const fs::path dir = scratch_dir();
  std::string text = read_file(example("rigid_body_pd.toml"));
  text.replace(text.find("inertia = [1.0, 2.0, 3.0]"), 25, "inertia = [1e300, 1e300, 1e300]");
  write_file(dir / "j.toml", text);
  const auto r = run_cli(dir, "run j.toml --out o");
  EXPECT_EQ(r.exit_code, 2);
  expect_one_error_line(r);
  EXPECT_NE(r.err.find("j.toml:9:11: body.inertia: an entry of 1e+300 kg m^2 is beyond the usable range"),
            std::string::npos) << r.err;
}

// A failed run says so beside its partial rows: summary.json.partial holds status "partial",
// the exit code and the error.
TEST(CliContract, FailedRunWritesAPartialStatus) {
  const fs::path dir = scratch_dir();
  std::string stiff = read_file(example("rigid_body_pd.toml"));
  stiff.replace(stiff.find("inertia = [1.0, 2.0, 3.0]"), 25, "inertia = [1e-3, 1e3, 1e3]");
  stiff.replace(stiff.find("step = 0.01"), 11, "step = 0.05");
  write_file(dir / "stiff.toml", stiff);
  ASSERT_EQ(run_cli(dir, "run stiff.toml --out o").exit_code, 3);
  const std::string status = read_file(dir / "o/summary.json.partial");
  EXPECT_NE(status.find("\"status\": \"partial\""), std::string::npos) << status;
  EXPECT_NE(status.find("\"exit_code\": 3"), std::string::npos) << status;
  EXPECT_NE(status.find("non-finite state"), std::string::npos) << status;
  EXPECT_TRUE(fs::exists(dir / "o/trajectory.csv.partial"));
  EXPECT_FALSE(fs::exists(dir / "o/summary.json"));
}

// A reach analysis that fails numerically (the nominal itself overflows: ω̇ = 10³⁰⁰ ω) leaves
// reach.json.partial with its status instead of nothing. (An enclosure that diverges is no longer
// such a failure: it ends the cell's analysis with cannot_prove, docs/reach.md "Adaptive steps".)
TEST(CliContract, FailedReachWritesAPartialReachJson) {
  const fs::path dir = scratch_dir();
  const std::string text =
      "kind = \"reach\"\n[system]\nmodel = \"linear_omega\"\n"
      "matrix = [[1e300, 0.0, 0.0], [0.0, 1e300, 0.0], [0.0, 0.0, 1e300]]\n"
      "[initial]\nattitude_radius = 0.1\nomega_b = [0.65, 0.54, 0.61]\nomega_radius = 0.1\n"
      "[reach]\nhorizon = 1.0\nsteps = 10\n[soundness]\nsamples = 0\n";
  write_file(dir / "wide.toml", text);
  const auto r = run_cli(dir, "reach wide.toml --out o");
  EXPECT_EQ(r.exit_code, 3) << r.err;
  expect_one_error_line(r);
  EXPECT_FALSE(fs::exists(dir / "o/reach.json"));
  const std::string status = read_file(dir / "o/reach.json.partial");
  EXPECT_NE(status.find("\"status\": \"partial\""), std::string::npos) << status;
  // The partial file records the same reason the error line gives, with the exit code.
  const auto j = nlohmann::json::parse(status);
  EXPECT_EQ(j["exit_code"].get<int>(), 3);
  const std::string reason = j["error"].get<std::string>();
  EXPECT_FALSE(reason.empty());
  EXPECT_NE(r.err.find(reason), std::string::npos) << r.err << "\n" << status;
}

// SIGINT and SIGTERM in the middle of a run end it with exit 3 and leave trajectory.csv.partial
// (its rows so far), the status summary.json.partial and no trajectory.csv or summary.json that
// would look complete (every command: tests/cli/test_output_folder.cpp).
TEST(CliContract, InterruptedRunLeavesOnlyAPartialFile) {
  const fs::path dir = scratch_dir();
  std::string text = read_file(example("pet_erg_paper.toml"));
  text.replace(text.find("step = 0.01"), 11, "step = 1e-4");          // 10^7 steps: ~15 s
  text.replace(text.find("duration = 60.0"), 15, "duration = 1000.0");
  text.replace(text.find("output_interval = 0.01"), 22, "output_interval = 0.1");
  write_file(dir / "long.toml", text);
  for (const char* sig : {"INT", "TERM"}) {
    SCOPED_TRACE(sig);
    const fs::path out = dir / (std::string("out_") + sig);
    // env --default-signal: a background job of a non-interactive shell ignores SIGINT.
    const std::string script = "cd " + quoted(dir.string()) + " && env --default-signal=INT " +
                               quoted(ATTIGUARD_CLI_PATH) + " run long.toml --out " +
                               quoted(out.string()) + " >/dev/null 2>&1 & p=$!; while [ ! -s " +
                               quoted((out / "trajectory.csv.partial").string()) +
                               " ]; do sleep 0.05; done; kill -" + sig + " $p; wait $p";
    const int status = std::system(("sh -c " + quoted(script)).c_str());
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 3);
    EXPECT_NE(read_file(out / "summary.json.partial").find(std::string("interrupted by SIG") + sig),
              std::string::npos);
    EXPECT_TRUE(fs::exists(out / "trajectory.csv.partial"));
    EXPECT_EQ(read_file(out / "trajectory.csv.partial").rfind("t,", 0), 0u);
    EXPECT_FALSE(fs::exists(out / "trajectory.csv"));
    EXPECT_FALSE(fs::exists(out / "summary.json"));
  }
}

// Re-using an output folder for another kind removes the earlier run's figures (recorded in
// plots.txt), so none is left beside the new summary.
TEST(CliContract, EarlierPlotsAreRemovedByTheNextRun) {
  const fs::path dir = scratch_dir();
  const auto first = run_cli(dir, "run " + quoted(example("rigid_body_pd.toml").string()) + " --out o --plot");
  ASSERT_EQ(first.exit_code, 0) << first.err;
  if (first.err.find("no plots:") != std::string::npos) GTEST_SKIP() << first.err;
  ASSERT_TRUE(fs::exists(dir / "o/attitude_error.png"));
  write_file(dir / "o/mine.png", "not attiguard's");
  const auto second = run_cli(dir, "run " + quoted(example("pet_erg_paper.toml").string()) + " --out o");
  ASSERT_EQ(second.exit_code, 0) << second.err;
  for (const char* png : {"attitude_error.png", "angular_velocity.png", "torque.png",
                          "quaternion.png", "energy_momentum.png"}) {
    EXPECT_FALSE(fs::exists(dir / "o" / png)) << png;
  }
  EXPECT_FALSE(fs::exists(dir / "o/plots.txt"));
  EXPECT_TRUE(fs::exists(dir / "o/mine.png"));  // not written by attiguard: kept
}

// Each output folder records the resolved scenario: the file with every default its readers
// used filled in; running it again gives the same results.
TEST(CliContract, RunWritesTheResolvedScenarioThatReproducesIt) {
  const fs::path dir = scratch_dir();
  for (const char* name : {"rigid_body_pd.toml", "pet_erg_paper.toml"}) {
    SCOPED_TRACE(name);
    const auto first = run_cli(dir, "run " + quoted(example(name).string()) + " --out a");
    ASSERT_EQ(first.exit_code, 0) << first.err;
    EXPECT_NE(first.out.find("a/scenario.resolved.toml"), std::string::npos) << first.out;
    const std::string resolved = read_file(dir / "a/scenario.resolved.toml");
    EXPECT_NE(resolved.find("abs_tol = "), std::string::npos) << resolved;  // a default
    EXPECT_NE(resolved.find("max_step = 0.0"), std::string::npos) << resolved;
    ASSERT_EQ(run_cli(dir, "run a/scenario.resolved.toml --out b").exit_code, 0);
    auto without_wall_time = [](std::string s) {
      const auto at = s.find("\"wall_time_s\"");
      if (at != std::string::npos) s.erase(at, s.find('\n', at) - at);
      return s;
    };
    EXPECT_EQ(without_wall_time(read_file(dir / "a/summary.json")),
              without_wall_time(read_file(dir / "b/summary.json")));
    EXPECT_EQ(read_file(dir / "a/trajectory.csv"), read_file(dir / "b/trajectory.csv"));
  }
}

TEST(CliContract, MissingScenarioFileIsInvalidInput) {
  const auto r = run_cli(scratch_dir(), "check does_not_exist.toml");
  EXPECT_EQ(r.exit_code, 2);
  expect_one_error_line(r);
  EXPECT_NE(r.err.find("does_not_exist.toml"), std::string::npos);
}

TEST(CliContract, TomlSyntaxErrorNamesFileAndLine) {
  const fs::path dir = scratch_dir();
  write_file(dir / "broken.toml", "kind = \"rigid_body\"\nname = = 3\n");
  for (const char* args : {"check broken.toml", "run broken.toml --out o"}) {
    SCOPED_TRACE(args);
    const auto r = run_cli(dir, args);
    EXPECT_EQ(r.exit_code, 2);
    expect_one_error_line(r);
    EXPECT_NE(r.err.find("broken.toml:2:"), std::string::npos) << r.err;
  }
}

TEST(CliContract, UnknownKindListsTheKnownOnes) {
  const fs::path dir = scratch_dir();
  write_file(dir / "nope.toml", "kind = \"no_such_kind\"\n");
  const auto r = run_cli(dir, "check nope.toml");
  EXPECT_EQ(r.exit_code, 2);
  expect_one_error_line(r);
  EXPECT_NE(r.err.find("no_such_kind"), std::string::npos);
  for (const auto& kind : attiguard::app::kinds()) {
    EXPECT_NE(r.err.find(std::string(kind.name)), std::string::npos) << r.err;
  }
}

TEST(CliContract, OutputDirectoryThatCannotBeCreatedIsInvalidInput) {
  const fs::path scenario = example("rigid_body_pd.toml");
  if (!fs::exists(scenario)) GTEST_SKIP() << "no " << scenario;
  const fs::path dir = scratch_dir();
  write_file(dir / "a_file", "");
  const auto r = run_cli(dir, "run " + quoted(scenario.string()) + " --out a_file/sub");
  EXPECT_EQ(r.exit_code, 2);
  expect_one_error_line(r);
}

TEST(CliContract, RunWithoutPythonStillSucceedsAndSaysWhy) {
  const fs::path scenario = example("rigid_body_pd.toml");
  if (!fs::exists(scenario)) GTEST_SKIP() << "no " << scenario;
  const fs::path dir = scratch_dir();
  const auto r = run_cli(dir, "run " + quoted(scenario.string()) + " --out out --plot",
                         "ATTIGUARD_PYTHON=/nonexistent/python3");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(count_lines(r.err), 1u) << r.err;
  EXPECT_NE(r.err.find("no plots:"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_regular_file(dir / "out" / "trajectory.csv"));
  EXPECT_TRUE(fs::is_regular_file(dir / "out" / "summary.json"));
  EXPECT_FALSE(fs::exists(dir / "out" / "attitude_error.png"));
}

TEST(CliContract, PlottingFailureIsOneErrorLine) {
  const fs::path scenario = example("rigid_body_pd.toml");
  if (!fs::exists(scenario)) GTEST_SKIP() << "no " << scenario;
  const fs::path dir = scratch_dir();
  // A stand-in interpreter that fails like a Python traceback does.
  write_file(dir / "failing_python",
             "#!/bin/sh\necho 'Traceback (most recent call last):' >&2\n"
             "echo 'ValueError: broken plot' >&2\nexit 1\n");
  fs::permissions(dir / "failing_python", fs::perms::owner_all);
  const auto r = run_cli(dir, "run " + quoted(scenario.string()) + " --out out --plot",
                         "ATTIGUARD_PYTHON=" + quoted((dir / "failing_python").string()));
  EXPECT_EQ(r.exit_code, 3);
  expect_one_error_line(r);
  EXPECT_NE(r.err.find("ValueError: broken plot"), std::string::npos) << r.err;
}

TEST(CliContract, RunWithPlotWritesTheFigures) {
  const fs::path scenario = example("rigid_body_pd.toml");
  if (!fs::exists(scenario)) GTEST_SKIP() << "no " << scenario;
  const fs::path dir = scratch_dir();
  const auto r = run_cli(dir, "run " + quoted(scenario.string()) + " --out out --plot");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  if (r.err.find("no plots:") != std::string::npos) GTEST_SKIP() << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  for (const char* png : {"attitude_error.png", "angular_velocity.png", "torque.png",
                          "quaternion.png", "energy_momentum.png"}) {
    EXPECT_GT(fs::file_size(dir / "out" / png), 1000u) << png;
    EXPECT_NE(r.out.find(png), std::string::npos) << "run does not list " << png;
  }
}

#endif  // ATTIGUARD_CLI_PATH
