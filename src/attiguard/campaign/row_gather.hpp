#pragma once
/// @file row_gather.hpp
/// Gathering the runs.csv rows computed on every MPI rank onto rank 0 (docs/scaling.md).

#include <map>
#include <string>

#include "attiguard/parallel/mpi_world.hpp"

namespace attiguard::campaign {

/// Every rank's rows (run index → CSV line without newline), merged on rank 0; other ranks get
/// an empty map. Collective. One rank: `mine`.
[[nodiscard]] std::map<long, std::string> gather_rows(const std::map<long, std::string>& mine,
                                                      const parallel::World& world);

}  // namespace attiguard::campaign
