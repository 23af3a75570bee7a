/// @file check_command.cpp
/// `attiguard check SCENARIO`: validation without running.

#include <iostream>
#include <string>

#include "attiguard/scenario/dispersion.hpp"
#include "attiguard/cli/commands.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/app/kinds.hpp"

namespace attiguard::cli {

void check_command(const std::filesystem::path& scenario_path) {
  const scenario::Document doc = scenario::load_document(scenario_path);
  if (doc.has_top_level("dispersions")) {  // a campaign scenario (docs/campaigns.md)
    const scenario::Document nominal = scenario::nominal_document(doc);
    const app::KindHandler& handler = app::handler_for(nominal);
    const scenario::DispersionPlan plan = scenario::read_dispersions(doc);
    handler.check(nominal);
    std::cout << "OK: " << scenario_path.string() << " (" << handler.name << ", campaign with "
              << plan.items.size() << " dispersion(s))\n";
    return;
  }
  const app::KindHandler& handler = app::handler_for(doc);
  handler.check(doc);
  // The report first: it may refuse what only the set-up finds (the planned mode plans).
  const std::string report = handler.check_report != nullptr ? handler.check_report(doc) : std::string();
  std::cout << "OK: " << scenario_path.string() << " (" << handler.name << ")\n" << report;
}

}  // namespace attiguard::cli
