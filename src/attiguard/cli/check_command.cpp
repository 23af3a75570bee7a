/// @file check_command.cpp
/// `attiguard check SCENARIO.toml`: validation without running.

#include <iostream>

#include "attiguard/cli/commands.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/kinds.hpp"

namespace attiguard::cli {

void check_command(const std::filesystem::path& scenario_path) {
  const scenario::Document doc = scenario::load_document(scenario_path);
  const scenario::KindHandler& handler = scenario::handler_for(doc);
  handler.check(doc);
  std::cout << "OK: " << scenario_path.string() << " (" << handler.name << ")\n";
}

}  // namespace attiguard::cli
