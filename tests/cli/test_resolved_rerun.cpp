// Every example's resolved scenario re-runs to identical outputs (docs/conventions.md,
// "Outputs", the resolved scenario; issue 27, deliverable 2). One test per examples/*.toml, so a
// new example is covered without editing this file:
//   - a `run` or `reach` example: the command of its kind on the example into A, then on
//     A/scenario.resolved.toml into B; the same exit code, the same files, every file
//     byte-identical except summary.json / reach.json (equal once every wall_time_s key, at any
//     depth, is dropped) and scenario.resolved.toml (equal below its header comment: resolving
//     the resolved scenario adds nothing);
//   - a campaign example ([dispersions]): `campaign --runs 2 --seed 1` of the example and of
//     its A/scenario.resolved.toml give the same runs.csv byte for byte; `--replay 1` writes
//     run_1/scenario.resolved.toml, and `attiguard run` of it gives the replay's trajectory.csv
//     byte for byte and its summary.json (but wall_time_s).
// Kind reach is the heavy one: at full length the six reach pairs took 74 s (and 122 s at
// another time) in Release on the shared 2-core machine, every other example < 0.2 s a run, so
// the whole test would take 80 to 130 s. A reach example of more than kReachSteps steps runs a
// copy whose [reach] horizon and steps are cut to kReachSteps steps of the same length, and
// both A and B run that copy's scenario; the others (10 steps or fewer) and every other
// example run as they are.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace attiguard::test::resolved_rerun {

namespace fs = std::filesystem;

/// Steps of a shortened reach example (of the length its own steps have).
constexpr int kReachSteps = 10;

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

struct Result {
  int exit_code{-1};
  std::string err;
};

/// `attiguard ARGS` run in `dir`.
Result attiguard(const fs::path& dir, const std::string& args) {
  const std::string cmd = "cd " + quoted(dir.string()) + " && " + quoted(ATTIGUARD_CLI_PATH) +
                          " " + args + " >stdout.txt 2>stderr.txt";
  const int status = std::system(cmd.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status),
          read_text(dir / "stderr.txt")};
}

/// The value of the top-level `kind = "…"` line.
std::string kind_of(const std::string& text) {
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("kind", 0) == 0 && line.find('=') != std::string::npos) {
      const auto a = line.find('"');
      return line.substr(a + 1, line.find('"', a + 1) - a - 1);
    }
  }
  return {};
}

bool is_campaign(const std::string& text) {
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line == "[dispersions]") return true;
  }
  return false;
}

/// `text` with the [reach] table's horizon and steps cut to kReachSteps steps of the same
/// length (so integrator_step <= horizon/(steps*substeps) still holds); `text` itself when it
/// has no more steps.
std::string shortened_reach(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  std::string table;
  double horizon = 0.0;
  int steps = 0;
  for (const std::string& line : lines) {
    if (line.rfind('[', 0) == 0) table = line.substr(0, line.find(']') + 1);
    if (table != "[reach]") continue;
    if (line.rfind("horizon", 0) == 0) horizon = std::stod(line.substr(line.find('=') + 1));
    if (line.rfind("steps", 0) == 0) steps = std::stoi(line.substr(line.find('=') + 1));
  }
  EXPECT_GT(horizon, 0.0) << "no [reach] horizon";
  EXPECT_GT(steps, 0) << "no [reach] steps";
  if (steps <= kReachSteps) return text;
  const int cut = kReachSteps;
  std::ostringstream out;
  table.clear();
  for (const std::string& line : lines) {
    if (line.rfind('[', 0) == 0) table = line.substr(0, line.find(']') + 1);
    if (table == "[reach]" && line.rfind("horizon", 0) == 0) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "horizon = %.17g", horizon * cut / steps);
      out << buf << '\n';
    } else if (table == "[reach]" && line.rfind("steps", 0) == 0) {
      out << "steps = " << cut << '\n';
    } else {
      out << line << '\n';
    }
  }
  return out.str();
}

/// `j` without its wall_time_s keys, at every depth.
nlohmann::json without_wall_times(nlohmann::json j) {
  if (j.is_object()) {
    j.erase("wall_time_s");
    for (auto& [key, value] : j.items()) value = without_wall_times(value);
  } else if (j.is_array()) {
    for (auto& value : j) value = without_wall_times(value);
  }
  return j;
}

/// The text of a resolved scenario below its header comment (which names its source).
std::string below_header(const std::string& text) {
  EXPECT_EQ(text.rfind("# ", 0), 0u) << text.substr(0, 200);
  return text.substr(text.find('\n') + 1);
}

std::set<std::string> files_in(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.is_regular_file()) names.insert(e.path().filename().string());
  }
  return names;
}

/// Every file of `a` and `b` agrees as the header says.
void expect_same_outputs(const fs::path& a, const fs::path& b) {
  ASSERT_EQ(files_in(a), files_in(b));
  for (const std::string& name : files_in(a)) {
    SCOPED_TRACE(name);
    const std::string x = read_text(a / name);
    const std::string y = read_text(b / name);
    if (name == "summary.json" || name == "reach.json") {
      EXPECT_EQ(without_wall_times(nlohmann::json::parse(x)),
                without_wall_times(nlohmann::json::parse(y)));
    } else if (name == "scenario.resolved.toml") {
      EXPECT_EQ(below_header(x), below_header(y));
    } else {
      EXPECT_TRUE(x == y) << "differs (" << x.size() << " and " << y.size() << " bytes)";
    }
  }
}

std::vector<std::string> example_names() {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(fs::path(ATTIGUARD_SOURCE_DIR) / "examples")) {
    if (e.path().extension() == ".toml") names.push_back(e.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

class ResolvedRerun : public ::testing::TestWithParam<std::string> {};

TEST_P(ResolvedRerun, GivesIdenticalOutputs) {
  const std::string name = GetParam();
  const fs::path example = fs::path(ATTIGUARD_SOURCE_DIR) / "examples" / (name + ".toml");
  const fs::path dir = fs::temp_directory_path() /
                       ("attiguard_resolved_rerun_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string text = read_text(example);
  const std::string kind = kind_of(text);
  ASSERT_FALSE(kind.empty()) << example;

  if (is_campaign(text)) {
    const std::string runs = " --runs 2 --seed 1 --threads 1";
    const Result a = attiguard(dir, "campaign " + quoted(example.string()) + runs + " --out a");
    ASSERT_TRUE(fs::exists(dir / "a/scenario.resolved.toml")) << a.err;
    const Result b = attiguard(dir, "campaign a/scenario.resolved.toml" + runs + " --out b");
    EXPECT_EQ(a.exit_code, b.exit_code) << a.err << b.err;
    EXPECT_EQ(read_text(dir / "a/runs.csv"), read_text(dir / "b/runs.csv"));
    EXPECT_EQ(below_header(read_text(dir / "a/scenario.resolved.toml")),
              below_header(read_text(dir / "b/scenario.resolved.toml")));

    const Result replay =
        attiguard(dir, "campaign " + quoted(example.string()) + " --seed 1 --replay 1 --out a");
    ASSERT_TRUE(fs::exists(dir / "a/run_1/scenario.resolved.toml")) << replay.err;
    const Result rerun = attiguard(dir, "run a/run_1/scenario.resolved.toml --out c");
    ASSERT_EQ(rerun.exit_code, replay.exit_code) << replay.err << rerun.err;
    EXPECT_TRUE(read_text(dir / "a/run_1/trajectory.csv") == read_text(dir / "c/trajectory.csv"));
    EXPECT_EQ(without_wall_times(nlohmann::json::parse(read_text(dir / "a/run_1/summary.json"))),
              without_wall_times(nlohmann::json::parse(read_text(dir / "c/summary.json"))));
  } else {
    const std::string command = kind == "reach" ? "reach " : "run ";
    fs::path scenario = example;
    if (kind == "reach" && shortened_reach(text) != text) {
      scenario = dir / (name + ".toml");
      std::ofstream(scenario, std::ios::binary) << shortened_reach(text);
    }
    const Result a = attiguard(dir, command + quoted(scenario.string()) + " --out a");
    ASSERT_TRUE(fs::exists(dir / "a/scenario.resolved.toml")) << a.err;
    ASSERT_NE(a.exit_code, 2) << a.err;
    const Result b = attiguard(dir, command + "a/scenario.resolved.toml --out b");
    ASSERT_EQ(a.exit_code, b.exit_code) << a.err << b.err;
    expect_same_outputs(dir / "a", dir / "b");
  }
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Examples, ResolvedRerun, ::testing::ValuesIn(example_names()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

}  // namespace attiguard::test::resolved_rerun
