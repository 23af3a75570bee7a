#pragma once
/// @file tune_command.hpp
/// `[mpirun -n R] attiguard tune SCENARIO --out DIR [--threads N] [--budget RUNS] [--seed S]
/// [--batch B] [--range KEY=MIN:MAX]... [--no-plot]` (docs/pet-erg.md, section "Tuning"); the
/// scenario's `[tune]` table (scenario/tune_table.hpp) gives budget, seed, batch, ranges and plot
/// where no flag does.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace attiguard::cli {

/// Arguments of `attiguard tune`; an empty optional (no flag) leaves the key to `[tune]`, then to
/// the default (budget 64, seed 1, batch 4, plot on).
struct TuneArguments {
  std::filesystem::path scenario;
  std::filesystem::path out_dir;
  int threads{1};                   ///< worker threads per rank
  std::optional<long> budget;
  std::optional<long> batch;        ///< points per refinement batch (default 4)
  std::optional<std::uint64_t> seed;
  std::vector<std::string> ranges;  ///< "KEY=MIN:MAX": replaces `[tune.ranges]` and the default space
  std::optional<bool> plot;         ///< false: --no-plot
};

/// Searches the gains on this process's threads, or over the MPI ranks it was started among
/// (every rank calls it; rank 0 alone prints and writes); writes DIR/tune.json, DIR/best (the best scenario)
/// and DIR/tune_tradeoff.png. Throws VerificationFailure (exit 4, on every rank) when no
/// evaluated point converged with every constraint kept.
void tune_command(const TuneArguments& args);

}  // namespace attiguard::cli
