#include "attiguard/campaign/aggregation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <string>

#include "attiguard/campaign/csv_format.hpp"

namespace attiguard::campaign {

namespace {
/// Failed/rejected runs listed individually in campaign.json (all are in runs.csv).
constexpr std::size_t kMaxListed = 100;
}  // namespace

double percentile(const std::vector<double>& sorted, double p) {
  if (sorted.empty()) return std::nan("");
  const double rank = std::ceil(p / 100.0 * static_cast<double>(sorted.size()));
  const std::size_t i = rank < 1.0 ? 0 : static_cast<std::size_t>(rank) - 1;
  return sorted[std::min(i, sorted.size() - 1)];
}

namespace {

/// The counts of the rows of runs.csv and the values of their figures, column by column.
struct RowTally {
  long ok = 0, rejected = 0, failed = 0, violations = 0;
  std::vector<std::vector<double>> values;  ///< per header column: the non-empty figures of ok rows
  nlohmann::json listed = nlohmann::json::array();     ///< failed or rejected runs (kMaxListed)
  nlohmann::json violating = nlohmann::json::array();  ///< runs with a violation (kMaxListed)
  std::map<std::string, long> outcomes;
};

/// The columns aggregate() reads; `outcome` is header.size() when the kind has none.
struct Columns {
  std::size_t status, reason, violation, outcome, count;
  explicit Columns(const std::vector<std::string>& header) : count(header.size()) {
    const auto col = [&](const std::string& name) {
      return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
    };
    status = col("status");
    reason = col("reason");
    violation = col("violation");
    outcome = col("outcome");
  }
};

/// Counts every row of `rows` whose field count matches the header.
RowTally tally_rows(const Columns& cols, const std::map<long, std::string>& rows) {
  RowTally t;
  t.values.resize(cols.count);
  for (const auto& [index, line] : rows) {
    const std::vector<std::string> f = csv_split(line);
    if (f.size() != cols.count) continue;
    const std::string& status = f[cols.status];
    if (status == "ok") {
      ++t.ok;
      if (cols.outcome < cols.count) ++t.outcomes[f[cols.outcome]];
      if (f[cols.violation] == "1") {
        ++t.violations;
        if (t.violating.size() < kMaxListed) t.violating.push_back(index);
      }
      for (std::size_t i = cols.violation + 1; i < cols.count; ++i) {
        if (f[i].empty()) continue;
        t.values[i].push_back(std::strtod(f[i].c_str(), nullptr));
      }
    } else {
      (status == "rejected" ? t.rejected : t.failed) += 1;
      if (t.listed.size() < kMaxListed) {
        t.listed.push_back({{"run", index}, {"status", status}, {"reason", f[cols.reason]}});
      }
    }
  }
  return t;
}

/// The statistics of one figure's values (unsorted, non-empty). `count`: the runs the
/// statistics are over (a figure that is null in a run, e.g. the convergence time of a run that
/// did not converge, is left out of them).
nlohmann::json figure_statistics(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  double sum = 0.0;
  for (double x : v) sum += x;
  return {{"count", static_cast<long>(v.size())},
          {"min", v.front()},
          {"p1", percentile(v, 1)},
          {"p5", percentile(v, 5)},
          {"p50", percentile(v, 50)},
          {"p95", percentile(v, 95)},
          {"p99", percentile(v, 99)},
          {"max", v.back()},
          {"mean", sum / static_cast<double>(v.size())}};
}

}  // namespace

nlohmann::json aggregate(const CampaignInfo& info, const std::vector<std::string>& header,
                         const std::map<long, std::string>& rows) {
  const Columns cols(header);
  const RowTally t = tally_rows(cols, rows);
  nlohmann::json j;
  j["scenario"] = info.scenario;
  j["kind"] = info.kind;
  j["seed"] = info.seed;
  j["runs_requested"] = info.runs;
  j["runs_completed"] = static_cast<long>(rows.size());
  j["max_attempts"] = info.max_attempts;
  j["dispersed"] = info.dispersed;
  j["ok"] = t.ok;
  j["rejected"] = t.rejected;
  j["failures"] = t.failed;
  j["violations"] = t.violations;
  j["violating_runs"] = t.violating;
  if (cols.outcome < cols.count) {
    nlohmann::json counts = nlohmann::json::object();
    for (const auto& [name, n] : t.outcomes) counts[name.empty() ? "unknown" : name] = n;
    j["outcomes"] = counts;
  }
  j["failed_or_rejected_runs"] = t.listed;
  nlohmann::json pct = nlohmann::json::object();
  for (std::size_t i = cols.violation + 1; i < cols.count; ++i) {
    if (!t.values[i].empty()) pct[header[i]] = figure_statistics(t.values[i]);
  }
  j["figures"] = pct;
  return j;
}

std::string outcome_counts_text(const nlohmann::json& outcomes) {
  std::string text;
  for (const auto& [name, n] : outcomes.items()) {
    if (!text.empty()) text += ", ";
    text += std::to_string(n.get<long>()) + " " + name;
  }
  return text.empty() ? "none" : text;
}

}  // namespace attiguard::campaign
