#include "attiguard/app/campaign_runner.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <string_view>

#include "attiguard/campaign/csv_format.hpp"
#include "attiguard/campaign/retain_sink.hpp"
#include "attiguard/campaign/seed.hpp"
#include "attiguard/core/errors.hpp"
#include "attiguard/core/one_line.hpp"
#include "attiguard/parallel/worker_pool.hpp"

namespace attiguard::app {

using campaign::format_number;
using campaign::csv_quote;
using campaign::Rng;
using campaign::run_seed;

namespace {

bool is_figure(const std::string& key, const nlohmann::json& v) {
  if (key == "wall_time_s" || key == "output_rows") return false;
  // null: a figure the nominal run does not have (e.g. no convergence, no violation) that a
  // dispersed run may have; its column stays empty where it is null.
  return v.is_number() || v.is_boolean() || v.is_null();
}

}  // namespace

const char* status_name(RunStatus s) noexcept {
  const std::string_view name = kRunStatusNames.name(s);  // a string literal: NUL-terminated
  return name == "?" ? "failed" : name.data();
}

Campaign load_campaign(const std::filesystem::path& path, std::uint64_t seed,
                       const std::filesystem::path& scratch) {
  const scenario::Document doc = scenario::load_document(path);
  Campaign c;
  c.seed = seed;
  c.nominal = scenario::nominal_document(doc);
  c.handler = &handler_for(c.nominal);
  if (c.handler->name == "reach") {
    throw InputError(path.string() + ": kind 'reach' is an analysis, not a run: campaigns need a "
                                     "kind that `attiguard run` runs");
  }
  c.plan = scenario::read_dispersions(doc);
  c.handler->check(c.nominal);
  scenario::check_dispersion_bounds(c.plan, doc, c.handler->check);
  RunOptions options;
  options.out_dir = scratch;
  options.write_files = false;
  campaign::RetainSink retained(c.plan.retain);  // validates the retained columns
  if (c.plan.retain.enabled()) options.rows = &retained;
  nlohmann::json summary;
  try {
    summary = c.handler->run(c.nominal, options);
  } catch (const InputError& e) {
    constexpr std::string_view kInterval = "[campaign] retain_interval: ";
    if (const std::string_view what = e.what(); what.starts_with(kInterval)) {
      scenario::fail_in_table(doc, "campaign", "retain_interval", what.substr(kInterval.size()));
    }
    if (std::string_view(e.what()).starts_with("[campaign] retain")) {
      throw InputError(path.string() + ": " + e.what());
    }
    throw;
  }
  c.retain_times = retained.times();
  for (const auto& [key, value] : summary.items()) {
    if (is_figure(key, value)) c.figures.push_back(key);
  }
  const auto outcome = summary.find("outcome");
  c.outcome_column = outcome != summary.end() && outcome->is_string();
  return c;
}

scenario::Document dispersed_document(const Campaign& c, Rng& rng, std::vector<double>& values) {
  scenario::Document d = c.nominal;
  values.clear();
  scenario::apply_dispersions(c.plan, c.nominal, rng, d, values);
  return d;
}

RunRecord run_one(const Campaign& c, long k, const RunOptions& options, scenario::Document* drawn) {
  RunRecord r;
  r.index = k;
  r.seed = run_seed(c.seed, static_cast<std::uint64_t>(k));
  Rng rng(r.seed);
  scenario::Document doc;
  for (;;) {
    ++r.attempts;
    try {
      doc = dispersed_document(c, rng, r.values);
      if (drawn != nullptr) *drawn = doc;
      c.handler->check(doc);
      r.reason.clear();
      break;
    } catch (const std::exception& e) {
      r.reason = one_line(e.what());
      if (r.attempts >= c.plan.max_attempts) {
        r.status = RunStatus::rejected;
        return r;
      }
    }
  }
  campaign::RetainSink retained(c.plan.retain);
  RunOptions run_options = options;
  if (c.plan.retain.enabled()) run_options.rows = &retained;
  try {
    r.summary = c.handler->run(doc, run_options);
    r.retained = retained.values();
    r.retained_samples = retained.samples();
  } catch (const std::exception& e) {
    r.status = RunStatus::failed;
    r.reason = one_line(e.what());
    r.summary = nullptr;
    return r;
  }
  for (const std::string& key : c.figures) {
    const auto it = r.summary.find(key);
    if (it == r.summary.end()) continue;
    if (it->is_number_float() && !std::isfinite(it->get<double>())) {
      r.status = RunStatus::failed;
      r.reason = "non-finite summary figure " + key;
      return r;
    }
  }
  // A violation: a constraint flag `*_satisfied` is false. A flight that did not complete is
  // not a violation: its `outcome` (incomplete, stalled, ...) is counted separately.
  for (const auto& [key, value] : r.summary.items()) {
    if (value.is_boolean() && !value.get<bool>() && key.ends_with("_satisfied")) {
      r.violation = true;
    }
  }
  return r;
}

std::vector<std::string> csv_columns(const Campaign& c) {
  std::vector<std::string> cols{"run", "seed", "attempts", "status", "reason"};
  for (const std::string& s : scenario::dispersion_columns(c.plan)) cols.push_back(s);
  if (c.outcome_column) cols.push_back("outcome");
  cols.push_back("violation");
  for (const std::string& s : c.figures) cols.push_back(s);
  return cols;
}

std::string csv_header(const Campaign& c) {
  std::string s;
  for (const std::string& col : csv_columns(c)) s += (s.empty() ? "" : ",") + col;
  return s;
}

std::string csv_row(const Campaign& c, const RunRecord& r) {
  // Appends one at a time (GCC 12 reports a false -Wrestrict on chained operator+).
  std::string line = std::to_string(r.index);
  for (const std::string& field : {std::to_string(r.seed), std::to_string(r.attempts),
                                   std::string(status_name(r.status)), csv_quote(r.reason)}) {
    line.append(1, ',').append(field);
  }
  for (double v : r.values) line.append(1, ',').append(format_number(v));
  const bool ok = r.status == RunStatus::ok;
  if (c.outcome_column) {
    const auto it = ok ? r.summary.find("outcome") : r.summary.end();
    line.append(1, ',');
    if (ok && it != r.summary.end() && it->is_string()) line.append(csv_quote(it->get<std::string>()));
  }
  line += ok ? (r.violation ? ",1" : ",0") : ",";
  for (const std::string& key : c.figures) {
    line += ",";
    if (!ok) continue;
    const auto it = r.summary.find(key);
    if (it == r.summary.end() || it->is_null()) continue;
    if (it->is_boolean()) {
      line += it->get<bool>() ? "1" : "0";
    } else if (it->is_number()) {
      line.append(format_number(it->get<double>()));
    }
  }
  return line;
}

void run_many(const Campaign& c, const std::vector<long>& indices, int threads,
              const std::filesystem::path& scratch, const std::atomic<bool>& stop,
              const std::function<void(const RunRecord&)>& on_done) {
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::mutex done_mutex;
  auto work = [&](long worker) {
    RunOptions options;
    options.out_dir = scratch / ("worker" + std::to_string(worker));
    options.write_files = false;
    for (std::size_t i = next++; i < indices.size() && !stop.load() && !failed.load(); i = next++) {
      try {
        const RunRecord r = run_one(c, indices[i], options);
        std::lock_guard<std::mutex> lock(done_mutex);
        on_done(r);
      } catch (...) {  // out of memory, a runs.csv that cannot be written: the others stop too
        failed.store(true);
        throw;  // rethrown to the caller by run_workers
      }
    }
  };
  // A thread the system refuses is a ThreadStartError before any run (parallel/worker_pool.hpp).
  parallel::run_workers(std::max(1L, std::min<long>(threads, static_cast<long>(indices.size()))), work);
}

}  // namespace attiguard::app
