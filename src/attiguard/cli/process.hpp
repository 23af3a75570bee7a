#pragma once
/// @file process.hpp
/// Runs a child program without a shell and collects its exit status and output.

#include <string>
#include <vector>

namespace attiguard::cli {

/// How a child process ended.
struct ProcessResult {
  int spawn_error{0};   ///< errno of a failed start (e.g. ENOENT: program not found); 0 if started
  bool exited{false};   ///< true when it exited normally (then exit_status is meaningful)
  int exit_status{-1};  ///< exit status when exited
  int signal{0};        ///< terminating signal when killed
  std::string out;      ///< everything it wrote on stdout
  std::string err;      ///< everything it wrote on stderr
};

/// Runs argv[0] (searched in PATH when it has no slash) with arguments argv and environment env
/// ("NAME=value" entries), stdin from /dev/null, stdout and stderr captured. Blocks until the
/// child ends. Throws std::system_error only when the pipes cannot be set up.
[[nodiscard]] ProcessResult run_process(const std::vector<std::string>& argv,
                                        const std::vector<std::string>& env);

}  // namespace attiguard::cli
