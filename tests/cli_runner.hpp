#pragma once
/// Runs the `attiguard` program in tests and captures its exit code, stdout and stderr.

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace attiguard::test {

struct CliResult {
  int exit_code{-1};
  std::string out;
  std::string err;
};

inline std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// A fresh, empty temporary directory for one test.
inline std::filesystem::path fresh_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("attiguard_test_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// Runs `attiguard ARGS` (ARGS already shell-quoted) from the source directory.
inline CliResult run_cli(const std::string& args) {
  const auto dir = fresh_dir("cli_io");
  const std::string cmd = std::string("cd '") + ATTIGUARD_SOURCE_DIR + "' && '" +
                          ATTIGUARD_CLI_PATH + "' " + args + " >'" + (dir / "out").string() +
                          "' 2>'" + (dir / "err").string() + "'";
  const int status = std::system(cmd.c_str());
  CliResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = read_file(dir / "out");
  r.err = read_file(dir / "err");
  std::filesystem::remove_all(dir);
  return r;
}

/// Number of lines in s (a trailing newline does not start a new line).
inline long count_lines(const std::string& s) {
  long n = 0;
  for (char c : s) {
    n += c == '\n';
  }
  return n + (!s.empty() && s.back() != '\n');
}

}  // namespace attiguard::test
