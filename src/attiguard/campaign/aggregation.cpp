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

nlohmann::json aggregate(const CampaignInfo& info, const std::vector<std::string>& header,
                         const std::map<long, std::string>& rows) {
  const auto col = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  const std::size_t status_col = col("status");
  const std::size_t reason_col = col("reason");
  const std::size_t violation_col = col("violation");
  const std::size_t outcome_col = col("outcome");  // header.size() when the kind has none
  long ok = 0, rejected = 0, failed = 0, violations = 0;
  std::vector<std::vector<double>> values(header.size());
  nlohmann::json listed = nlohmann::json::array();
  nlohmann::json violating = nlohmann::json::array();
  std::map<std::string, long> outcomes;
  for (const auto& [index, line] : rows) {
    const std::vector<std::string> f = csv_split(line);
    if (f.size() != header.size()) continue;
    const std::string& status = f[status_col];
    if (status == "ok") {
      ++ok;
      if (outcome_col < header.size()) ++outcomes[f[outcome_col]];
      if (f[violation_col] == "1") {
        ++violations;
        if (violating.size() < kMaxListed) violating.push_back(index);
      }
      for (std::size_t i = violation_col + 1; i < header.size(); ++i) {
        if (f[i].empty()) continue;
        values[i].push_back(std::strtod(f[i].c_str(), nullptr));
      }
    } else {
      (status == "rejected" ? rejected : failed) += 1;
      if (listed.size() < kMaxListed) {
        listed.push_back({{"run", index}, {"status", status}, {"reason", f[reason_col]}});
      }
    }
  }
  nlohmann::json j;
  j["scenario"] = info.scenario;
  j["kind"] = info.kind;
  j["seed"] = info.seed;
  j["runs_requested"] = info.runs;
  j["runs_completed"] = static_cast<long>(rows.size());
  j["max_attempts"] = info.max_attempts;
  j["dispersed"] = info.dispersed;
  j["ok"] = ok;
  j["rejected"] = rejected;
  j["failures"] = failed;
  j["violations"] = violations;
  j["violating_runs"] = violating;
  if (outcome_col < header.size()) {
    nlohmann::json counts = nlohmann::json::object();
    for (const auto& [name, n] : outcomes) counts[name.empty() ? "unknown" : name] = n;
    j["outcomes"] = counts;
  }
  j["failed_or_rejected_runs"] = listed;
  nlohmann::json pct = nlohmann::json::object();
  for (std::size_t i = violation_col + 1; i < header.size(); ++i) {
    std::vector<double> v = values[i];
    if (v.empty()) continue;
    std::sort(v.begin(), v.end());
    double sum = 0.0;
    for (double x : v) sum += x;
    // `count`: the runs the statistics are over (a figure that is null in a run, e.g. the
    // convergence time of a run that did not converge, is left out of them).
    pct[header[i]] = {{"count", static_cast<long>(v.size())},
                      {"min", v.front()},
                      {"p1", percentile(v, 1)},
                      {"p5", percentile(v, 5)},
                      {"p50", percentile(v, 50)},
                      {"p95", percentile(v, 95)},
                      {"p99", percentile(v, 99)},
                      {"max", v.back()},
                      {"mean", sum / static_cast<double>(v.size())}};
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
