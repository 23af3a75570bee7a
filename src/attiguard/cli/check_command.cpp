/// @file check_command.cpp
/// `attiguard check SCENARIO.toml`: validation without running.

#include <iostream>

#include "attiguard/campaign/dispersion.hpp"
#include "attiguard/cli/commands.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/kinds.hpp"

namespace attiguard::cli {

void check_command(const std::filesystem::path& scenario_path) {
  const scenario::Document doc = scenario::load_document(scenario_path);
  if (doc.root.contains("dispersions")) {  // a campaign scenario (docs/campaigns.md)
    const scenario::Document nominal = campaign::nominal_document(doc);
    const scenario::KindHandler& handler = scenario::handler_for(nominal);
    const campaign::DispersionPlan plan = campaign::read_dispersions(doc);
    handler.check(nominal);
    std::cout << "OK: " << scenario_path.string() << " (" << handler.name << ", campaign with "
              << plan.items.size() << " dispersion(s))\n";
    return;
  }
  const scenario::KindHandler& handler = scenario::handler_for(doc);
  handler.check(doc);
  std::cout << "OK: " << scenario_path.string() << " (" << handler.name << ")\n";
}

}  // namespace attiguard::cli
