#include "attiguard/campaign/mpi_split.hpp"

#include <cstdlib>
#include <mutex>

#ifdef ATTIGUARD_HAVE_MPI
#include <mpi.h>
#endif

namespace attiguard::campaign {

namespace {

/// Serialises rows as "index\tline\n" (lines never contain tabs or newlines).
std::string pack(const std::map<long, std::string>& rows) {
  std::string s;
  for (const auto& [index, line] : rows) s += std::to_string(index) + '\t' + line + '\n';
  return s;
}

void unpack(const std::string& s, std::map<long, std::string>& rows) {
  std::size_t pos = 0;
  while (pos < s.size()) {
    const std::size_t tab = s.find('\t', pos);
    const std::size_t nl = s.find('\n', tab);
    if (tab == std::string::npos || nl == std::string::npos) break;
    rows[std::atol(s.substr(pos, tab - pos).c_str())] = s.substr(tab + 1, nl - tab - 1);
    pos = nl + 1;
  }
}

[[maybe_unused]] bool launched_by_mpi() {
  for (const char* var : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "MPI_LOCALNRANKS"}) {
    if (std::getenv(var) != nullptr) return true;
  }
  return false;
}

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

std::map<long, std::string> gather_rows(const std::map<long, std::string>& mine,
                                        const World& world) {
  if (world.size == 1) return mine;
  std::map<long, std::string> all;
#ifdef ATTIGUARD_HAVE_MPI
  const std::string packed = pack(mine);
  int length = static_cast<int>(packed.size());
  std::vector<int> lengths(static_cast<std::size_t>(world.size));
  MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::vector<int> displs(lengths.size(), 0);
  int total = 0;
  for (std::size_t r = 0; r < lengths.size(); ++r) {
    displs[r] = total;
    total += lengths[r];
  }
  std::string buffer(world.root() ? static_cast<std::size_t>(total) : 0, '\0');
  MPI_Gatherv(packed.data(), length, MPI_CHAR, buffer.data(), lengths.data(), displs.data(),
              MPI_CHAR, 0, MPI_COMM_WORLD);
  if (world.root()) unpack(buffer, all);
#else
  (void)unpack;
  (void)pack;
  all = mine;
#endif
  return all;
}

void barrier(const World& world) {
#ifdef ATTIGUARD_HAVE_MPI
  if (world.size > 1) MPI_Barrier(MPI_COMM_WORLD);
#else
  (void)world;
#endif
}

}  // namespace attiguard::campaign
