#pragma once
/// @file mpi_world.hpp
/// The MPI ranks this process belongs to, and the few collectives attiguard needs to split
/// independent work items (campaign runs, reach partition cells) over them and gather the
/// results. Built with MPI only when CMake found it (ATTIGUARD_HAVE_MPI); MPI is initialised only
/// when the program was started by mpirun/srun (their environment variables are set), so the
/// same binary also runs on its own as rank 0 of 1. See docs/scaling.md.

#include <string>
#include <vector>

namespace attiguard::parallel {

/// This process's place among the ranks (rank 0 of 1 without MPI).
struct World {
  int rank{0};
  int size{1};
  [[nodiscard]] bool root() const noexcept { return rank == 0; }
};

/// True when the binary was built with MPI.
[[nodiscard]] bool mpi_built() noexcept;

/// Initialises MPI once (when built with it and launched by an MPI launcher; finalised at
/// exit) and returns the world; {0, 1} otherwise.
[[nodiscard]] World mpi_world();

/// The items of `todo` this rank handles: positions p with p mod size == rank (round robin, so
/// every rank gets a similar mix of items).
[[nodiscard]] std::vector<long> rank_share(const std::vector<long>& todo, const World& world);

/// Every rank's `mine` bytes, in rank order, on rank 0 (other ranks get an empty vector).
/// Collective. One rank: {mine}.
[[nodiscard]] std::vector<std::string> gather_bytes(const std::string& mine, const World& world);

/// Every rank's `mine` bytes, in rank order, on every rank. Collective. One rank: {mine}.
[[nodiscard]] std::vector<std::string> allgather_bytes(const std::string& mine, const World& world);

/// Barrier across ranks (no-op on one rank). Collective.
void barrier(const World& world);

}  // namespace attiguard::parallel
