#pragma once
/// @file tune_batch.hpp
/// One batch of `attiguard tune` candidates evaluated over the MPI ranks and the threads of each
/// rank (docs/pet-erg.md, section 15): the candidates are dealt round robin over the ranks
/// (parallel::rank_share), each rank's share over its worker threads; every rank then receives
/// every point, encoded exactly (every double bit for bit), so that all ranks take the same next
/// decision of the search. No MPI header here: the exchange is parallel/mpi_world's.

#include <atomic>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "attiguard/app/tune_search.hpp"
#include "attiguard/parallel/mpi_world.hpp"
#include "attiguard/scenario/document.hpp"

namespace attiguard::app {

/// Evaluates `candidates` (values in `parameters` order; with no parameter, the scenario as
/// given) with evaluate_candidate on this rank's share and `threads` (≥ 1) workers, in
/// `scratch`/worker<w>; returns every candidate's point, in candidate order, on every rank.
/// A candidate whose evaluation throws does not skip the exchange (the other ranks would wait
/// for ever): after it, every rank raises the error of the lowest such candidate (its exit
/// code and message, whatever the split). Once `stop` is set and true (the interruption flag),
/// the workers take no further candidate: those not evaluated come back with status "stopped",
/// on every rank alike (docs/pet-erg.md, section 15, "Interruption"). Collective over `world`.
[[nodiscard]] std::vector<TunePoint> evaluate_tune_batch(
    const scenario::Document& nominal, const std::vector<TuneParameter>& parameters,
    const std::vector<std::vector<double>>& candidates, int threads,
    const std::filesystem::path& scratch, const parallel::World& world,
    const std::atomic<bool>* stop = nullptr);

/// Runs `step` on this rank, then exchanges whether it threw: when it threw on any rank, every
/// rank raises the error of the lowest such rank (its exit code and message), so that a failure
/// on one rank only (rank 0's output directory, say) does not leave the others waiting in the
/// search's first exchange. Collective over `world`; one rank: runs `step`.
void run_on_every_rank(const std::function<void()>& step, const parallel::World& world);

/// Points of one rank on their way to the others: candidate position, the evaluation's error
/// ("" or "<exit code> <message>") and the point (when there was no error).
struct TuneBatchShare {
  std::vector<long> positions;
  std::vector<std::string> failures;
  std::vector<TunePoint> points;
};

/// The share as bytes (CBOR; every double exact).
[[nodiscard]] std::string encode_tune_share(const TuneBatchShare& share);

/// Inverse of encode_tune_share. Throws NumericalError for bytes that are not such an encoding.
[[nodiscard]] TuneBatchShare decode_tune_share(const std::string& bytes);

}  // namespace attiguard::app
