/// @file plot_command.cpp
/// `--plot`: runs the Python plotting subpackage attiguard.plot (python/package/attiguard/plot)
/// on a finished run. It needs neither the compiled extension attiguard._core nor an installed
/// package: PYTHONPATH leads with python/package of the source tree (docs/conventions.md).
///
/// Exit statuses of `python3 -m attiguard.plot` (python/package/attiguard/plot/__init__.py):
///   0 plots written (their paths on stdout, one per line);
///   2 usage error, unknown scenario kind or unreadable result files (one line on stderr);
///   69 numpy or matplotlib is not installed for that interpreter (one line on stderr saying
///      which and how to install it);
///   anything else: an unexpected error (Python traceback on stderr).

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "attiguard/cli/commands.hpp"
#include "attiguard/cli/process.hpp"
#include "attiguard/io/output_records.hpp"

extern char** environ;  // NOLINT: POSIX

namespace attiguard::cli {
namespace {

/// Exit status of attiguard.plot when numpy or matplotlib is missing (EX_UNAVAILABLE).
constexpr int kPlotDependencyMissing = 69;

constexpr std::string_view kInstallHint = "apt-get install python3-matplotlib python3-numpy";

/// Value of an environment variable, or `fallback` when unset or empty.
std::string env_or(const char* name, const char* fallback) {
  const char* value = std::getenv(name);
  return (value != nullptr && *value != '\0') ? std::string(value) : std::string(fallback);
}

/// The last non-empty line of a program's output, trimmed.
std::string last_line(const std::string& text) {
  std::size_t end = text.find_last_not_of(" \t\r\n");
  if (end == std::string::npos) return {};
  std::size_t begin = text.rfind('\n', end);
  begin = (begin == std::string::npos) ? 0 : begin + 1;
  return text.substr(begin, end - begin + 1);
}

/// Removes `prefix` from the start of `s` when present.
std::string without_prefix(std::string s, std::string_view prefix) {
  if (s.starts_with(prefix)) s.erase(0, prefix.size());
  return s;
}

/// The child's environment: ours, with PYTHONPATH led by the package directory, bytecode
/// writing off (the source tree may be read-only) and matplotlib's non-interactive backend.
std::vector<std::string> child_environment(const std::string& python_dir) {
  std::vector<std::string> env;
  std::string pythonpath = python_dir;
  for (char** e = environ; e != nullptr && *e != nullptr; ++e) {
    std::string_view entry(*e);
    if (entry.starts_with("PYTHONPATH=")) {
      const auto old = entry.substr(std::strlen("PYTHONPATH="));
      if (!old.empty()) pythonpath.append(":").append(old);
      continue;
    }
    if (entry.starts_with("MPLBACKEND=") || entry.starts_with("PYTHONDONTWRITEBYTECODE=")) {
      continue;
    }
    env.emplace_back(entry);
  }
  env.push_back("PYTHONPATH=" + pythonpath);
  env.emplace_back("PYTHONDONTWRITEBYTECODE=1");
  env.emplace_back("MPLBACKEND=Agg");
  return env;
}

/// The plotting module and the directory holding its top-level package `attiguard`: the
/// source tree's python/package (ATTIGUARD_SOURCE_PYTHON_DIR is python/).
constexpr const char* kPlotModule = "attiguard.plot";
constexpr const char* kDefaultPackageDir = ATTIGUARD_SOURCE_PYTHON_DIR "/package";

}  // namespace

PlotOutcome plot_results(const std::string& kind, const std::filesystem::path& dir) {
  const std::string python = env_or("ATTIGUARD_PYTHON", ATTIGUARD_PYTHON);
  const std::string python_dir = env_or("ATTIGUARD_PYTHON_DIR", kDefaultPackageDir);
  PlotOutcome outcome;

  std::error_code ec;
  if (!std::filesystem::is_regular_file(
          std::filesystem::path(python_dir) / "attiguard" / "plot" / "__main__.py", ec)) {
    outcome.skipped_because = std::string("the plotting package ") + kPlotModule +
                              " is not in " + python_dir +
                              " (set ATTIGUARD_PYTHON_DIR to the python/package directory of "
                              "attiguard, or to a site-packages holding attiguard)";
    return outcome;
  }

  const ProcessResult r = run_process({python, "-m", kPlotModule, kind, dir.string()},
                                      child_environment(python_dir));
  if (r.spawn_error != 0) {
    outcome.skipped_because = "cannot start the Python interpreter " + python + " (" +
                              std::strerror(r.spawn_error) + "; apt-get install python3 " +
                              "python3-matplotlib python3-numpy, or set ATTIGUARD_PYTHON)";
    return outcome;
  }
  if (r.exited && r.exit_status == kPlotDependencyMissing) {
    std::string why = without_prefix(last_line(r.err), std::string(kPlotModule) + ": ");
    if (why.empty()) {
      why = "numpy or matplotlib is not installed for " + python + " (" +
            std::string(kInstallHint) + ")";
    }
    outcome.skipped_because = why;
    return outcome;
  }
  if (!r.exited || r.exit_status != 0) {
    const std::string how = r.exited ? "exited with status " + std::to_string(r.exit_status)
                                     : "was killed by signal " + std::to_string(r.signal);
    std::string detail = last_line(r.err);
    throw std::runtime_error("plotting failed: " + python + " -m " + kPlotModule + " " + how +
                             (detail.empty() ? std::string() : ": " + detail) +
                             " (the results in " + dir.string() + " were written)");
  }

  std::size_t pos = 0;
  while (pos < r.out.size()) {
    std::size_t end = r.out.find('\n', pos);
    if (end == std::string::npos) end = r.out.size();
    std::string line = r.out.substr(pos, end - pos);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (!line.empty()) outcome.written.emplace_back(line);
    pos = end + 1;
  }
  return outcome;
}

std::optional<std::string> list_plots(const std::string& kind, const std::filesystem::path& dir) {
  const PlotOutcome p = plot_results(kind, dir);
  io::record_plots(dir, p.written);
  for (const auto& w : p.written) std::cout << "  " << w.string() << '\n';
  return p.skipped_because;
}

void print_plots(const std::string& kind, const std::filesystem::path& dir) {
  if (const auto why = list_plots(kind, dir)) std::cerr << "attiguard: warning: no plots: " << *why << '\n';
}

}  // namespace attiguard::cli
