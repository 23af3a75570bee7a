#pragma once
/// @file tune_command.hpp
/// `attiguard tune SCENARIO --out DIR [--threads N] [--budget RUNS] [--seed S]
/// [--range KEY=MIN:MAX]... [--no-plot]` (docs/pet-erg.md, section "Tuning").

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace attiguard::cli {

/// Arguments of `attiguard tune`.
struct TuneArguments {
  std::filesystem::path scenario;
  std::filesystem::path out_dir;
  int threads{1};
  long budget{64};
  std::uint64_t seed{1};
  std::vector<std::string> ranges;  ///< "KEY=MIN:MAX": replaces the default space
  bool plot{true};
};

/// Searches the gains; writes DIR/tune.json, DIR/best (the best scenario) and DIR/tune_tradeoff.png. Throws
/// VerificationFailure (exit 4) when no evaluated point converged with every constraint kept.
void tune_command(const TuneArguments& args);

}  // namespace attiguard::cli
