#include "attiguard/reach/partition.hpp"

#include <new>

#include <cmath>
#include <numeric>
#include <string>

#include "attiguard/core/errors.hpp"
#include "attiguard/parallel/parallel_for.hpp"
#include "attiguard/reach/result_codec.hpp"

namespace attiguard::reach {

namespace {
/// Grid points of the cover of the ball of radius a in R³ and the cell radius.
std::vector<Vec3> grid(double a, int n, double& cell_radius) {
  if (n <= 1) {
    cell_radius = a;
    return {Vec3::Zero()};
  }
  const double h = 2.0 * a / n;
  cell_radius = h * std::sqrt(3.0) / 2.0;
  std::vector<Vec3> pts;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      for (int k = 0; k < n; ++k) {
        const Vec3 p(-a + h * (i + 0.5), -a + h * (j + 0.5), -a + h * (k + 0.5));
        if (p.norm() <= a + cell_radius) pts.push_back(p);
      }
    }
  }
  return pts;
}

/// The failure code of a cell that ran out of memory: not an exit code; raise_first_failure
/// raises std::bad_alloc for it, so that the caller refuses the thread count at its key
/// (docs/errors.md, "No abort"), never "std::bad_alloc" as a numerical failure.
constexpr int kOutOfMemory = 0;

/// This rank's cells (indices `share`) on `threads`. A failing cell must not skip the collective
/// that follows (the other ranks would wait for ever), so failures are recorded per cell —
/// "" or "<exit code> <message>" — and raised after the exchange.
void run_share(const ClosedLoop& loop, const std::vector<InitialSet>& cells, const std::vector<long>& share,
               const ConReachSettings& settings, int threads, std::vector<ReachResult>& mine,
               std::vector<std::string>& failure) {
  mine.resize(share.size());
  failure.resize(share.size());
  parallel::parallel_for(static_cast<long>(share.size()), threads, [&](long p) {
    const auto q = static_cast<std::size_t>(p);
    try {
      mine[q] = run_conreach(loop, cells[static_cast<std::size_t>(share[q])], settings);
    } catch (const std::bad_alloc&) {  // raised as std::bad_alloc again (raise_first_failure)
      failure[q] = std::to_string(kOutOfMemory) + " out of memory";
    } catch (const Error& e) {
      failure[q] = std::to_string(static_cast<int>(e.code())) + ' ' + e.what();
    } catch (const std::exception& e) {
      failure[q] = std::to_string(static_cast<int>(ExitCode::numerical_failure)) + ' ' + e.what();
    }
  });
}

/// This rank's cells for the exchange: per cell, its index, its failure and its CBOR-encoded
/// result, length-prefixed.
std::string pack_share(const std::vector<long>& share, const std::vector<ReachResult>& mine,
                       const std::vector<std::string>& failure) {
  std::string packed;
  auto put = [&packed](const std::string& field) {
    packed += std::to_string(field.size()) + ':' + field;
  };
  for (std::size_t q = 0; q < share.size(); ++q) {
    put(std::to_string(share[q]));
    put(failure[q]);
    put(failure[q].empty() ? encode_result(mine[q]) : std::string());
  }
  return packed;
}

/// One rank's packed cells (pack_share) into `out` and `failures`, by cell index.
void unpack_share(const std::string& part, std::vector<ReachResult>& out, std::vector<std::string>& failures) {
  std::size_t pos = 0;
  auto take = [&part, &pos]() {
    const std::size_t colon = part.find(':', pos);
    if (colon == std::string::npos) throw NumericalError("reach: malformed cell exchange between ranks");
    const std::size_t n = std::stoul(part.substr(pos, colon - pos));
    std::string field = part.substr(colon + 1, n);
    pos = colon + 1 + n;
    return field;
  };
  while (pos < part.size()) {
    const auto cell = static_cast<std::size_t>(std::stol(take()));
    failures.at(cell) = take();
    const std::string bytes = take();
    if (failures[cell].empty()) out[cell] = decode_result(bytes);
  }
}

/// The failure of the lowest cell index, whatever the split (same message serial and MPI),
/// rethrown as the error of its exit code.
void raise_first_failure(const std::vector<std::string>& failures) {
  for (const std::string& f : failures) {
    if (f.empty()) continue;
    const std::size_t space = f.find(' ');
    const int code = std::stoi(f.substr(0, space));
    const std::string message = f.substr(space + 1);
    if (code == kOutOfMemory) throw std::bad_alloc();
    if (code == static_cast<int>(ExitCode::invalid_input)) throw InputError(message);
    if (code == static_cast<int>(ExitCode::verification_failed)) throw VerificationFailure(message);
    throw NumericalError(message);
  }
}

}  // namespace

std::vector<InitialSet> partition_initial_set(const InitialSet& whole, int n_att, int n_omega) {
  if (n_att < 1 || n_omega < 1 || n_att > 50 || n_omega > 50) {
    throw InputError("partition: cells per axis must be in [1, 50]");
  }
  double ra = 0.0;
  double rw = 0.0;
  const std::vector<Vec3> att = grid(whole.attitude_radius, n_att, ra);
  const std::vector<Vec3> om = grid(whole.omega_radius, n_omega, rw);
  std::vector<InitialSet> cells;
  for (const Vec3& eta : att) {
    for (const Vec3& v : om) {
      InitialSet c;
      c.R0 = whole.R0 * lie::exp(eta);
      c.attitude_radius = ra;
      c.omega0 = whole.omega0 + v;
      c.omega_radius = rw;
      c.P0 = whole.P0;
      cells.push_back(c);
    }
  }
  return cells;
}

std::vector<ReachResult> run_partitioned(const ClosedLoop& loop, const std::vector<InitialSet>& cells,
                                         const ConReachSettings& settings, int threads,
                                         const parallel::World& world) {
  std::vector<long> indices(cells.size());
  std::iota(indices.begin(), indices.end(), 0L);
  const std::vector<long> share = parallel::rank_share(indices, world);
  std::vector<ReachResult> mine;
  std::vector<std::string> failure;
  run_share(loop, cells, share, settings, threads, mine, failure);

  std::vector<ReachResult> out(cells.size());
  std::vector<std::string> failures(cells.size());
  if (world.size == 1) {
    for (std::size_t q = 0; q < share.size(); ++q) {
      out[static_cast<std::size_t>(share[q])] = std::move(mine[q]);
      failures[static_cast<std::size_t>(share[q])] = std::move(failure[q]);
    }
  } else {
    // Every rank receives every cell (so all ranks reach the same verdict and exit code).
    for (const std::string& part : parallel::allgather_bytes(pack_share(share, mine, failure), world)) {
      unpack_share(part, out, failures);
    }
  }
  raise_first_failure(failures);
  return out;
}

}  // namespace attiguard::reach
