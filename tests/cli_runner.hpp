#pragma once
/// Runs the `attiguard` program in tests and captures its exit code, stdout and stderr.

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "sanitizer_build.hpp"

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

/// A reach example (examples/NAME) as this build's tests run it: its path, relative to the source
/// directory, in Release; in the sanitized build a copy in a fresh directory whose [soundness]
/// `samples = N` is for_this_build(N, 100) (sanitizer_build.hpp).
inline std::filesystem::path reach_example_for_this_build(const std::string& name) {
  const std::filesystem::path source = std::filesystem::path("examples") / name;
  std::string text = read_file(std::filesystem::path(ATTIGUARD_SOURCE_DIR) / source);
  const std::string key = "\nsamples = ";
  const std::size_t at = text.find(key, text.find("[soundness]"));
  if (at == std::string::npos) return source;  // no [soundness] samples: the file as it is
  const std::size_t end = text.find_first_not_of("0123456789", at + key.size());
  if (kSanitizedWorkDivisor == 1) return source;
  const long n = std::stol(text.substr(at + key.size(), end - at - key.size()));
  text.replace(at + key.size(), end - at - key.size(), std::to_string(for_this_build(n, 100)));
  const std::filesystem::path copy = fresh_dir("example_" + name) / name;
  std::ofstream(copy) << text;
  return copy;
}

}  // namespace attiguard::test
