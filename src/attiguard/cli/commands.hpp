#pragma once
/// @file commands.hpp
/// The subcommands of the `attiguard` program (src/attiguard/cli/main.cpp parses the arguments).
///
/// Each command prints its normal output on stdout and reports failure by throwing
/// attiguard::Error (exit code from Error::code()) or any other std::exception (exit 3); main()
/// turns either into the single stderr line `attiguard: error: <message>`.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace attiguard::cli {

/// Arguments of `attiguard run`.
struct RunArguments {
  std::filesystem::path scenario;  ///< SCENARIO
  std::filesystem::path out_dir;   ///< --out DIR
  bool plot{false};                ///< --plot
  bool aem{false};                 ///< --aem: DIR/attitude.aem (docs/interop.md)
  bool view{false};                ///< --view: DIR/view.html (docs/viewer.md)
};

/// `attiguard run SCENARIO --out DIR [--plot]`: runs the scenario, writes
/// DIR/trajectory.csv and DIR/summary.json (and the plots with --plot), prints a short summary
/// and the paths written.
void run_command(const RunArguments& args);

/// `attiguard check SCENARIO`: parses and validates the scenario without running it and
/// prints `OK: <file> (<kind>)`.
void check_command(const std::filesystem::path& scenario);

/// What the plotting step produced.
struct PlotOutcome {
  std::vector<std::filesystem::path> written;  ///< PNG files, as reported by the Python module
  /// Set when no plots were made because Python, numpy or matplotlib is unavailable: one line
  /// saying why and how to fix it. The run itself still succeeds.
  std::optional<std::string> skipped_because;
};

/// Runs `PYTHON -m attiguard.plot KIND DIR` (no shell) with PYTHONPATH led by the directory
/// holding the package attiguard (python/package, docs/conventions.md). PYTHON is the
/// interpreter chosen at configure time (ATTIGUARD_PYTHON, normally /usr/bin/python3),
/// overridden by the environment variable ATTIGUARD_PYTHON; the package directory is
/// ATTIGUARD_SOURCE_PYTHON_DIR/package, overridden by ATTIGUARD_PYTHON_DIR. Throws std::runtime_error when the module fails for another reason
/// than a missing interpreter or package.
[[nodiscard]] PlotOutcome plot_results(const std::string& kind, const std::filesystem::path& dir);

/// plot_results(kind, dir), then the figures recorded in DIR/plots.txt (the next command in DIR
/// removes them; io/output_records.hpp) and each one printed ("  PATH" on stdout): the `--plot`
/// of a command (docs/conventions.md, "Outputs"). Returns why no plots were made, if so.
std::optional<std::string> list_plots(const std::string& kind, const std::filesystem::path& dir);

/// list_plots(kind, dir), and the warning "attiguard: warning: no plots: WHY" on stderr when
/// none were made (the command itself still succeeds).
void print_plots(const std::string& kind, const std::filesystem::path& dir);

}  // namespace attiguard::cli
