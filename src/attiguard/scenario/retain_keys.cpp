#include "attiguard/scenario/retain_keys.hpp"

#include <algorithm>
#include <string>

#include "attiguard/scenario/document_tree.hpp"

namespace attiguard::scenario {

campaign::RetainPlan read_retain(const TableReader& campaign, const Document& doc) {
  campaign::RetainPlan plan;
  plan.interval = campaign.number_or("retain_interval", plan.interval, NumberRule::positive());
  if (!campaign.has("retain")) return plan;
  const toml::table* table = root_table(doc)["campaign"].as_table();
  const toml::array* list = table != nullptr ? (*table)["retain"].as_array() : nullptr;
  if (list == nullptr || list->empty()) {
    campaign.fail("retain", "must be a non-empty array of trajectory column names, e.g. "
                            "[\"min_margin\", \"tau_norm\"]");
  }
  for (const toml::node& n : *list) {
    const auto* s = n.as_string();
    if (s == nullptr || s->get().empty()) {
      campaign.fail("retain", "every entry must be a non-empty string (a trajectory column name)");
    }
    const std::string name = s->get();
    if (std::find(plan.columns.begin(), plan.columns.end(), name) != plan.columns.end()) {
      campaign.fail("retain", "'" + name + "' is listed twice");
    }
    if (name.find(',') != std::string::npos) campaign.fail("retain", "a column name has no comma");
    plan.columns.push_back(name);
  }
  return plan;
}

}  // namespace attiguard::scenario
