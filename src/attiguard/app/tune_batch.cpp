// A batch of tune candidates over MPI ranks and threads (tune_batch.hpp; docs/pet-erg.md,
// section 15).

#include "attiguard/app/tune_batch.hpp"

#include <algorithm>
#include <atomic>
#include <numeric>

#include <nlohmann/json.hpp>

#include "attiguard/core/errors.hpp"
#include "attiguard/parallel/worker_pool.hpp"

namespace attiguard::app {

namespace {

nlohmann::json optional_number(const std::optional<double>& x) {
  return x ? nlohmann::json(*x) : nlohmann::json(nullptr);
}

std::optional<double> read_optional(const nlohmann::json& j) {
  if (j.is_null()) return std::nullopt;
  return j.get<double>();
}

/// "<exit code> <message>" of the exception being handled (3 for one outside attiguard's family).
std::string current_failure() {
  try {
    throw;
  } catch (const Error& e) {
    return std::to_string(static_cast<int>(e.code())) + ' ' + e.what();
  } catch (const std::exception& e) {
    return std::to_string(static_cast<int>(ExitCode::numerical_failure)) + ' ' + e.what();
  }
}

/// Raises the error "<exit code> <message>" with its family (InputError, VerificationFailure,
/// NumericalError for any other code).
[[noreturn]] void raise_failure(const std::string& failure) {
  const std::size_t space = failure.find(' ');
  const int code = std::stoi(failure.substr(0, space));
  const std::string message = space == std::string::npos ? std::string() : failure.substr(space + 1);
  if (code == static_cast<int>(ExitCode::invalid_input)) throw InputError(message);
  if (code == static_cast<int>(ExitCode::verification_failed)) throw VerificationFailure(message);
  throw NumericalError(message);
}

}  // namespace

void run_on_every_rank(const std::function<void()>& step, const parallel::World& world) {
  if (world.size == 1) {
    step();
    return;
  }
  std::string mine;
  try {
    step();
  } catch (const std::exception&) {
    mine = current_failure();
  }
  for (const std::string& failure : parallel::allgather_bytes(mine, world)) {
    if (!failure.empty()) raise_failure(failure);
  }
}

std::string encode_tune_share(const TuneBatchShare& share) {
  nlohmann::json entries = nlohmann::json::array();
  for (std::size_t q = 0; q < share.positions.size(); ++q) {
    const TunePoint& p = share.points[q];
    entries.push_back({{"i", share.positions[q]}, {"f", share.failures[q]}, {"v", p.values},
                       {"s", p.status}, {"o", p.outcome}, {"r", p.reason}, {"n", p.violations},
                       {"c", optional_number(p.convergence_time)}, {"q", optional_number(p.ratio)},
                       {"b", optional_number(p.bang_bang_time)}});
  }
  const std::vector<std::uint8_t> bytes = nlohmann::json::to_cbor(entries);
  return {bytes.begin(), bytes.end()};
}

TuneBatchShare decode_tune_share(const std::string& bytes) {
  TuneBatchShare share;
  try {
    const nlohmann::json entries = nlohmann::json::from_cbor(bytes);
    for (const nlohmann::json& e : entries) {
      TunePoint p;
      p.values = e.at("v").get<std::vector<double>>();
      p.status = e.at("s").get<std::string>();
      p.outcome = e.at("o").get<std::string>();
      p.reason = e.at("r").get<std::string>();
      p.violations = e.at("n").get<long>();
      p.convergence_time = read_optional(e.at("c"));
      p.ratio = read_optional(e.at("q"));
      p.bang_bang_time = read_optional(e.at("b"));
      share.positions.push_back(e.at("i").get<long>());
      share.failures.push_back(e.at("f").get<std::string>());
      share.points.push_back(std::move(p));
    }
  } catch (const nlohmann::json::exception& e) {
    throw NumericalError(std::string("attiguard tune: malformed exchange between ranks (") + e.what() + ")");
  }
  return share;
}

std::vector<TunePoint> evaluate_tune_batch(const scenario::Document& nominal,
                                           const std::vector<TuneParameter>& parameters,
                                           const std::vector<std::vector<double>>& candidates,
                                           int threads, const std::filesystem::path& scratch,
                                           const parallel::World& world,
                                           const std::atomic<bool>* stop) {
  std::vector<long> all(candidates.size());
  std::iota(all.begin(), all.end(), 0L);
  TuneBatchShare mine;
  mine.positions = parallel::rank_share(all, world);
  mine.failures.assign(mine.positions.size(), std::string());
  mine.points.assign(mine.positions.size(), TunePoint{});
  // Worker w of this rank takes the next candidate of the share; a throw is kept, not raised.
  std::atomic<std::size_t> next{0};
  const auto work = [&](long worker) {
    const std::filesystem::path dir = scratch / ("worker" + std::to_string(worker));
    for (std::size_t k = next++; k < mine.positions.size(); k = next++) {
      const auto& values = candidates[static_cast<std::size_t>(mine.positions[k])];
      if (stop != nullptr && stop->load(std::memory_order_relaxed)) {
        mine.points[k].values = values;  // not evaluated: the search was stopped first
        mine.points[k].status = "stopped";
        continue;
      }
      try {
        mine.points[k] = evaluate_candidate(nominal, parameters, values, dir);
      } catch (const std::exception&) {
        mine.failures[k] = current_failure();
      }
    }
  };
  // A thread the system refuses is a ThreadStartError before any point (parallel/worker_pool.hpp).
  parallel::run_workers(std::max(1L, std::min<long>(threads, static_cast<long>(mine.positions.size()))), work);
  std::vector<TunePoint> out(candidates.size());
  std::vector<std::string> failures(candidates.size());
  const auto place = [&](TuneBatchShare&& s) {
    for (std::size_t q = 0; q < s.positions.size(); ++q) {
      const auto k = static_cast<std::size_t>(s.positions[q]);
      out.at(k) = std::move(s.points[q]);
      failures.at(k) = std::move(s.failures[q]);
    }
  };
  if (world.size == 1) {
    place(std::move(mine));
  } else {
    for (const std::string& part : parallel::allgather_bytes(encode_tune_share(mine), world)) {
      place(decode_tune_share(part));
    }
  }
  for (const std::string& f : failures) {
    if (!f.empty()) raise_failure(f);
  }
  return out;
}

}  // namespace attiguard::app
