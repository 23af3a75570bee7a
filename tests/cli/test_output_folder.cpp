/// The output-folder contract of every command (docs/conventions.md, "Outputs";
/// src/attiguard/app/output_folder.hpp): a folder pre-filled by every other command ends up
/// holding only the files of the last command — the same files as that command writes into an
/// empty folder — and, when the command is stopped by SIGTERM, only .partial files and its status
/// (a campaign also keeps runs.csv and campaign_identity.json, its resume state).
#ifdef ATTIGUARD_CLI_PATH

#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "sanitizer_build.hpp"

namespace attiguard_output_folder_test {

namespace fs = std::filesystem;

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// `text` with `from` replaced by `to` (which must be there: a changed example fails here).
std::string edited(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

std::string example(const std::string& name) {
  return slurp(fs::path(ATTIGUARD_SOURCE_DIR) / "examples" / name);
}

/// The work folder of the test with its scenario files: quick versions of the examples for the
/// pre-fills and long ones to be interrupted.
fs::path work_dir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::temp_directory_path() / "attiguard_output_folder_tests" /
                       (std::string(info->name()) + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string pet = example("pet_erg_paper.toml");
  std::ofstream(dir / "pet.toml") << pet;
  std::ofstream(dir / "rigid.toml") << example("rigid_body_pd.toml");
  std::ofstream(dir / "camp.toml") << example("pet_erg_campaign.toml");
  const std::string reach = edited(edited(example("conreach_pd.toml"), "horizon = 2.0", "horizon = 0.4"),
                                   "\nsteps = 20", "\nsteps = 4");
  std::ofstream(dir / "reach.toml") << edited(reach, "samples = 10000", "samples = 50");
  // Long versions: 10^7 steps of a run; 10^5 soundness samples after the reach CSV files are
  // written; a campaign run of 1.5·10^6 steps for --replay (its nominal runs first); tune points of 6·10^4 steps.
  std::ofstream(dir / "long.toml")
      << edited(edited(edited(pet, "step = 0.01", "step = 1e-4"), "duration = 60.0", "duration = 1000.0"),
                "output_interval = 0.01", "output_interval = 0.1");
  std::ofstream(dir / "reach_long.toml") << edited(reach, "samples = 10000", "samples = 100000");
  // The sanitized build runs the numerics 15-20x slower: its replay steps 10x longer, so that the
  // nominal run before run 1 takes about the Release time (sanitizer_build.hpp).
  const std::string replay_step = attiguard::test::kSanitizedWorkDivisor == 1 ? "1e-4" : "1e-3";
  std::ofstream(dir / "camp_long.toml")
      << edited(edited(example("pet_erg_campaign.toml"), "\nstep = 0.01", "\nstep = " + replay_step),
                "duration = 60.0", "duration = 150.0");
  std::ofstream(dir / "tune_long.toml") << edited(pet, "step = 0.01", "step = 1e-3");
  return dir;
}

/// Single-quotes a string for /bin/sh.
std::string sh_quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

struct Ran {
  int exit_code{-1};
  std::string err;
};

/// `attiguard ARGS` in `dir`.
Ran attiguard(const fs::path& dir, const std::string& args) {
  const std::string cmd = "cd " + sh_quoted(dir.string()) + " && " + sh_quoted(ATTIGUARD_CLI_PATH) +
                          " " + args + " >stdout.txt 2>stderr.txt";
  const int status = std::system(cmd.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status), slurp(dir / "stderr.txt")};
}

/// The commands. Every folder under test is PARENT/run_1, so that `campaign --replay 1 --out
/// PARENT` writes into it like every other command given `--out PARENT/run_1`.
enum class Cmd { tune, campaign, replay, reach, run, view, export_aem, run_other_kind };

const std::vector<Cmd> kPrefillOrder{Cmd::tune, Cmd::campaign, Cmd::replay, Cmd::reach, Cmd::run,
                                     Cmd::view, Cmd::export_aem, Cmd::run_other_kind};

std::string name_of(Cmd c) {
  switch (c) {
    case Cmd::tune: return "tune";
    case Cmd::campaign: return "campaign";
    case Cmd::replay: return "replay";
    case Cmd::reach: return "reach";
    case Cmd::run: return "run";
    case Cmd::view: return "view";
    case Cmd::export_aem: return "export_aem";
    case Cmd::run_other_kind: return "run_other_kind";
  }
  return "?";
}

/// The quick command `c` into `parent`/run_1 (its figures too, where it makes any).
std::string args_of(Cmd c, const std::string& parent) {
  const std::string f = sh_quoted(parent + "/run_1");
  switch (c) {
    case Cmd::tune: return "tune pet.toml --budget 4 --range control.kp=4:6 --out " + f;
    case Cmd::campaign: return "campaign camp.toml --runs 2 --out " + f;
    case Cmd::replay: return "campaign camp.toml --replay 1 --view --aem --out " + sh_quoted(parent);
    case Cmd::reach: return "reach reach.toml --view --out " + f;
    case Cmd::run: return "run pet.toml --aem --view --plot --out " + f;
    case Cmd::view: return "view " + f;
    case Cmd::export_aem: return "export-aem " + f;
    case Cmd::run_other_kind: return "run rigid.toml --out " + f;
  }
  return {};
}

/// Runs `c` into `parent`/run_1 and expects it to succeed.
void run_command(const fs::path& work, Cmd c, const std::string& parent) {
  const Ran r = attiguard(work, args_of(c, parent));
  ASSERT_EQ(r.exit_code, 0) << name_of(c) << ": " << args_of(c, parent) << "\n" << r.err;
}

/// Every file and folder below `dir`, relative, folders ending in '/'.
std::set<std::string> listing(const fs::path& dir) {
  std::set<std::string> names;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(dir, ec); it != fs::recursive_directory_iterator();
       it.increment(ec)) {
    const std::string rel = fs::relative(it->path(), dir).string();
    names.insert(it->is_directory() ? rel + "/" : rel);
  }
  return names;
}

std::string joined(const std::set<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += n + " ";
  return s;
}

/// A folder pre-filled by every command but `target`, in kPrefillOrder (view and export-aem read
/// the run just before them), then `target`. Without `run`, the folder export-aem reads is that
/// of `attiguard reach`, which it refuses (issue 49: its trajectory.csv is the analysis'
/// nominal, not a run's attitude): there it must exit 2 naming reach.json.
void prefill_except(const fs::path& work, Cmd target, const std::string& parent) {
  for (Cmd c : kPrefillOrder) {
    if (c == target) continue;
    if (c == Cmd::export_aem && target == Cmd::run) {
      const Ran r = attiguard(work, args_of(c, parent));
      EXPECT_EQ(r.exit_code, 2) << r.err;
      EXPECT_NE(r.err.find("the folder of `attiguard reach` (reach.json)"), std::string::npos) << r.err;
      continue;
    }
    run_command(work, c, parent);
    if (::testing::Test::HasFatalFailure()) return;
  }
}

/// view and export-aem read the folder of the command before them (the last of the pre-fill,
/// a run of kind rigid_body); the other commands write a folder of their own.
bool reads_its_folder(Cmd c) { return c == Cmd::view || c == Cmd::export_aem; }

class OutputFolder : public ::testing::TestWithParam<Cmd> {};

// Pre-filled by every other command, the folder holds exactly the files the command writes into
// an empty folder (for view and export-aem: into the folder of the same run), with the same
// CSV bytes: nothing of the earlier commands is left, not their figures nor their view or AEM.
TEST_P(OutputFolder, HoldsOnlyTheFilesOfTheLastCommand) {
  const Cmd target = GetParam();
  const fs::path work = work_dir();
  prefill_except(work, target, "mixed");
  ASSERT_FALSE(HasFatalFailure());
  ASSERT_FALSE(listing(work / "mixed/run_1").empty());
  run_command(work, target, "mixed");
  ASSERT_FALSE(HasFatalFailure());

  if (reads_its_folder(target)) run_command(work, Cmd::run_other_kind, "alone");
  run_command(work, target, "alone");
  ASSERT_FALSE(HasFatalFailure());
  const std::set<std::string> mixed = listing(work / "mixed/run_1");
  const std::set<std::string> alone = listing(work / "alone/run_1");
  EXPECT_EQ(mixed, alone) << "pre-filled: " << joined(mixed) << "\nalone: " << joined(alone);
  for (const std::string& n : alone) {
    if (n.ends_with(".csv")) {
      EXPECT_EQ(slurp(work / "mixed/run_1" / n), slurp(work / "alone/run_1" / n)) << n;
    }
  }
  if (target == Cmd::view) {  // the view of the run in the folder, not of an earlier one
    EXPECT_NE(slurp(work / "mixed/run_1/view.html").find("\"kind\":\"rigid_body\""), std::string::npos);
  }
  fs::remove_all(work);
}

INSTANTIATE_TEST_SUITE_P(EveryCommand, OutputFolder,
                         ::testing::Values(Cmd::run, Cmd::reach, Cmd::campaign, Cmd::replay,
                                           Cmd::tune, Cmd::view, Cmd::export_aem),
                         [](const ::testing::TestParamInfo<Cmd>& i) { return name_of(i.param); });

/// The long command `c` into `parent`/run_1 (argv without the program) and the file whose
/// appearance shows that it is under way.
struct LongCommand {
  std::vector<std::string> argv;
  fs::path under_way;  ///< relative to the work folder
  std::size_t min_lines{1};
};

LongCommand long_command(Cmd c, const std::string& parent) {
  const std::string f = parent + "/run_1";
  switch (c) {
    case Cmd::run: return {{"run", "long.toml", "--out", f}, f + "/trajectory.csv.partial", 2};
    case Cmd::reach: return {{"reach", "reach_long.toml", "--out", f}, f + "/steps.csv", 1};
    case Cmd::campaign:
      return {{"campaign", "camp.toml", "--runs", "100000", "--out", f}, f + "/runs.csv", 3};
    case Cmd::replay:
      return {{"campaign", "camp_long.toml", "--replay", "1", "--out", parent}, f + "/trajectory.csv.partial", 2};
    case Cmd::tune:
      return {{"tune", "tune_long.toml", "--budget", "4", "--range", "control.kp=4:6", "--no-plot", "--out", f},
              "stdout.txt", 1};
    default: return {};
  }
}

std::size_t line_count(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::size_t n = 0;
  for (std::string line; std::getline(in, line);) ++n;
  return n;
}

class InterruptedFolder : public ::testing::TestWithParam<Cmd> {};

// SIGTERM while the command runs in a folder pre-filled by every other command: exit 3 with one
// error line saying so, and the folder holds only .partial files and the command's status
// (STATUS.partial: "status": "partial", exit code 3) — a campaign also its resume state.
TEST_P(InterruptedFolder, HoldsOnlyPartialFilesAndTheStatus) {
  const Cmd target = GetParam();
  const fs::path work = work_dir();
  prefill_except(work, target, "mixed");
  ASSERT_FALSE(HasFatalFailure());
  const LongCommand cmd = long_command(target, "mixed");
  fs::remove(work / "stdout.txt");

  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    if (::chdir(work.c_str()) != 0) ::_exit(127);
    const int out = ::open("stdout.txt", O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = ::open("stderr.txt", O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(out, STDOUT_FILENO);
    ::dup2(err, STDERR_FILENO);
    std::vector<char*> argv{const_cast<char*>(ATTIGUARD_CLI_PATH)};
    for (const std::string& a : cmd.argv) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(ATTIGUARD_CLI_PATH, argv.data());
    ::_exit(127);
  }
  // Wait (no time limit asserted) until the command is under way, then interrupt it.
  int status = 0;
  bool ended = false;
  while (!fs::exists(work / cmd.under_way) || line_count(work / cmd.under_way) < cmd.min_lines) {
    if (::waitpid(pid, &status, WNOHANG) == pid) {
      ended = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ASSERT_FALSE(ended) << "the command ended before it could be interrupted: " << slurp(work / "stderr.txt");
  ASSERT_EQ(::kill(pid, SIGTERM), 0);
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status)) << "status " << status;
  EXPECT_EQ(WEXITSTATUS(status), 3);
  const std::string err = slurp(work / "stderr.txt");
  EXPECT_EQ(err.rfind("attiguard: error: interrupted by SIGTERM: ", 0), 0u) << err;
  EXPECT_EQ(err.find('\n'), err.size() - 1) << err;

  const fs::path folder = work / "mixed/run_1";
  const std::set<std::string> kept_by_campaign{"runs.csv", "campaign_identity.json"};
  for (const std::string& n : listing(folder)) {
    if (target == Cmd::campaign && kept_by_campaign.contains(n)) continue;
    EXPECT_TRUE(n.ends_with(".partial")) << n << " in " << joined(listing(folder));
  }
  const std::map<Cmd, std::string> status_file{{Cmd::run, "summary.json.partial"},
                                               {Cmd::replay, "summary.json.partial"},
                                               {Cmd::reach, "reach.json.partial"},
                                               {Cmd::campaign, "campaign.json.partial"},
                                               {Cmd::tune, "tune.json.partial"}};
  const auto j = nlohmann::json::parse(slurp(folder / status_file.at(target)), nullptr, false);
  ASSERT_TRUE(j.is_object()) << status_file.at(target);
  EXPECT_EQ(j.value("status", ""), "partial");
  EXPECT_EQ(j.value("exit_code", 0), 3);
  EXPECT_NE(j.value("error", "").find("interrupted by SIGTERM"), std::string::npos);
  if (target == Cmd::campaign) {  // the campaign of the rows kept; --resume continues it
    EXPECT_EQ(j["result"].value("runs_completed", 0u), line_count(folder / "runs.csv") - 1);
  }
  fs::remove_all(work);
}

INSTANTIATE_TEST_SUITE_P(EveryLongCommand, InterruptedFolder,
                         ::testing::Values(Cmd::run, Cmd::reach, Cmd::campaign, Cmd::replay, Cmd::tune),
                         [](const ::testing::TestParamInfo<Cmd>& i) { return name_of(i.param); });

// A refused input (exit 2) leaves no earlier results that could be taken for its own: the folder
// of a run holds only the status of the refusal.
TEST(OutputFolderRefused, RefusedScenarioLeavesOnlyItsStatus) {
  const fs::path work = work_dir();
  run_command(work, Cmd::run, "mixed");
  ASSERT_FALSE(HasFatalFailure());
  std::ofstream(work / "bad.toml") << "kind = \"rigid_bod\"\n";
  const Ran r = attiguard(work, "run bad.toml --out mixed/run_1");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(listing(work / "mixed/run_1"), (std::set<std::string>{"summary.json.partial"}));
  const auto j = nlohmann::json::parse(slurp(work / "mixed/run_1/summary.json.partial"));
  EXPECT_EQ(j["exit_code"].get<int>(), 2);
  EXPECT_TRUE(j["kind"].is_null());
  EXPECT_NE(r.err.find(j["error"].get<std::string>()), std::string::npos) << r.err;
  fs::remove_all(work);
}

// view of a folder it cannot show (a tune's) removes a view.html left there and writes none; the
// folder's own results stay.
TEST(OutputFolderRefused, ViewThatCannotBeMadeLeavesNoEarlierView) {
  const fs::path work = work_dir();
  run_command(work, Cmd::run, "a");
  run_command(work, Cmd::tune, "b");
  ASSERT_FALSE(HasFatalFailure());
  fs::copy_file(work / "a/run_1/view.html", work / "b/run_1/view.html");
  const std::set<std::string> tuned = listing(work / "b/run_1");
  const Ran r = attiguard(work, "view b/run_1");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  std::set<std::string> expected = tuned;
  expected.erase("view.html");
  EXPECT_EQ(listing(work / "b/run_1"), expected);
  fs::remove_all(work);
}

// A tune that finds no admissible point (exit 4) writes its tune.json, a result, and leaves no
// best.toml of an earlier tune beside it.
TEST(OutputFolderRefused, TuneWithoutAdmissiblePointLeavesNoEarlierBest) {
  const fs::path work = work_dir();
  run_command(work, Cmd::tune, "a");
  ASSERT_FALSE(HasFatalFailure());
  ASSERT_TRUE(fs::exists(work / "a/run_1/best.toml"));
  const Ran r = attiguard(work, "tune pet.toml --budget 4 --no-plot --out a/run_1");
  ASSERT_EQ(r.exit_code, 4) << r.err;
  EXPECT_EQ(listing(work / "a/run_1"), (std::set<std::string>{"tune.json"}));
  fs::remove_all(work);
}

// A command's own input is never removed, even when it carries an output name: the resolved
// scenario of a folder re-run into that folder, the best.toml of a tune tuned again into it.
TEST(OutputFolderRefused, InputWithAnOutputNameIsKept) {
  const fs::path work = work_dir();
  run_command(work, Cmd::run_other_kind, "a");
  ASSERT_FALSE(HasFatalFailure());
  const std::string trajectory = slurp(work / "a/run_1/trajectory.csv");
  Ran r = attiguard(work, "run a/run_1/scenario.resolved.toml --out a/run_1");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(slurp(work / "a/run_1/trajectory.csv"), trajectory);
  run_command(work, Cmd::tune, "b");
  ASSERT_FALSE(HasFatalFailure());
  r = attiguard(work, "tune b/run_1/best.toml --budget 4 --range control.kp=4:6 --no-plot --out b/run_1");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(work / "b/run_1/best.toml"));
  fs::remove_all(work);
}

}  // namespace attiguard_output_folder_test

#endif  // ATTIGUARD_CLI_PATH
