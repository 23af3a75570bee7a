#pragma once
/// @file mpi_split.hpp
/// Splitting work over MPI ranks and gathering the results on rank 0. Built with MPI only when
/// CMake found it (ATTIGUARD_HAVE_MPI); MPI is initialised only when the program was started by
/// mpirun/srun (their environment variables are set), so the binary also runs on its own.

#include <map>
#include <string>
#include <vector>

namespace attiguard::campaign {

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
/// every rank gets a similar mix of runs).
[[nodiscard]] std::vector<long> rank_share(const std::vector<long>& todo, const World& world);

/// Gathers every rank's rows on rank 0 (merged; others get an empty map). Collective.
[[nodiscard]] std::map<long, std::string> gather_rows(const std::map<long, std::string>& mine,
                                                      const World& world);

/// Barrier across ranks (no-op on one rank). Collective.
void barrier(const World& world);

}  // namespace attiguard::campaign
