#pragma once
/// @file reach_command.hpp
/// `attiguard reach SCENARIO --out DIR [--plot]`: ConReach reachability analysis.

#include <filesystem>

namespace attiguard::cli {

/// Arguments of `attiguard reach`.
struct ReachArguments {
  std::filesystem::path scenario;  ///< SCENARIO (kind = "reach")
  std::filesystem::path out_dir;   ///< --out DIR
  bool plot{false};                ///< --plot
  bool view{false};                ///< --view: DIR/view.html (docs/viewer.md)
};

/// Runs the analysis, writes DIR/reach.json and the CSV files (and plots with --plot), prints
/// a short summary. Throws attiguard::Error (exit code from its code()).
void reach_command(const ReachArguments& args);

}  // namespace attiguard::cli
