#include "attiguard/parallel/mpi_world.hpp"

#include <cstdlib>
#include <mutex>

#ifdef ATTIGUARD_HAVE_MPI
#include <mpi.h>
#endif

namespace attiguard::parallel {

namespace {

[[maybe_unused]] bool launched_by_mpi() {
  for (const char* var : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "MPI_LOCALNRANKS"}) {
    if (std::getenv(var) != nullptr) return true;
  }
  return false;
}

#ifdef ATTIGUARD_HAVE_MPI
/// Gathers `mine` from every rank to rank 0 (`all` = false) or to every rank (`all` = true).
std::vector<std::string> exchange(const std::string& mine, const World& world, bool all) {
  int length = static_cast<int>(mine.size());
  std::vector<int> lengths(static_cast<std::size_t>(world.size));
  if (all) {
    MPI_Allgather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, MPI_COMM_WORLD);
  } else {
    MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  }
  const bool receives = all || world.root();
  std::vector<int> displs(lengths.size(), 0);
  int total = 0;
  for (std::size_t r = 0; r < lengths.size(); ++r) {
    displs[r] = total;
    total += receives ? lengths[r] : 0;
  }
  std::string buffer(static_cast<std::size_t>(total), '\0');
  if (all) {
    MPI_Allgatherv(mine.data(), length, MPI_CHAR, buffer.data(), lengths.data(), displs.data(),
                   MPI_CHAR, MPI_COMM_WORLD);
  } else {
    MPI_Gatherv(mine.data(), length, MPI_CHAR, buffer.data(), lengths.data(), displs.data(),
                MPI_CHAR, 0, MPI_COMM_WORLD);
  }
  std::vector<std::string> parts;
  if (!receives) return parts;
  for (std::size_t r = 0; r < lengths.size(); ++r) {
    parts.push_back(buffer.substr(static_cast<std::size_t>(displs[r]), static_cast<std::size_t>(lengths[r])));
  }
  return parts;
}
#endif

}  // namespace

bool mpi_built() noexcept {
#ifdef ATTIGUARD_HAVE_MPI
  return true;
#else
  return false;
#endif
}

World mpi_world() {
  static World world;
#ifdef ATTIGUARD_HAVE_MPI
  static std::once_flag once;
  std::call_once(once, [] {
    if (!launched_by_mpi()) return;
    int initialised = 0;
    MPI_Initialized(&initialised);
    if (!initialised) {
      MPI_Init(nullptr, nullptr);
      std::atexit([] {
        int finalised = 0;
        MPI_Finalized(&finalised);
        if (!finalised) MPI_Finalize();
      });
    }
    MPI_Comm_rank(MPI_COMM_WORLD, &world.rank);
    MPI_Comm_size(MPI_COMM_WORLD, &world.size);
  });
#endif
  return world;
}

std::vector<long> rank_share(const std::vector<long>& todo, const World& world) {
  std::vector<long> mine;
  for (std::size_t p = 0; p < todo.size(); ++p) {
    if (static_cast<int>(p % static_cast<std::size_t>(world.size)) == world.rank) {
      mine.push_back(todo[p]);
    }
  }
  return mine;
}

std::vector<std::string> gather_bytes(const std::string& mine, const World& world) {
#ifdef ATTIGUARD_HAVE_MPI
  if (world.size > 1) return exchange(mine, world, false);
#endif
  (void)world;
  return {mine};
}

std::vector<std::string> allgather_bytes(const std::string& mine, const World& world) {
#ifdef ATTIGUARD_HAVE_MPI
  if (world.size > 1) return exchange(mine, world, true);
#endif
  (void)world;
  return {mine};
}

void barrier(const World& world) {
#ifdef ATTIGUARD_HAVE_MPI
  if (world.size > 1) MPI_Barrier(MPI_COMM_WORLD);
#else
  (void)world;
#endif
}

}  // namespace attiguard::parallel
