#include "attiguard/scenario/kinds.hpp"

#include <array>
#include <string>

#include "attiguard/core/errors.hpp"
#include "attiguard/scenario/rigid_body_scenario.hpp"
#include "attiguard/scenario/table_reader.hpp"
#include "attiguard/sim/rigid_body_run.hpp"

namespace attiguard::scenario {

namespace {

void check_rigid_body(const Document& doc) { (void)parse_rigid_body(doc); }

nlohmann::json run_rigid_body(const Document& doc, const RunOptions& options) {
  return sim::run_rigid_body(parse_rigid_body(doc), options.out_dir);
}

constexpr std::array<KindHandler, 1> registry{{
    {"rigid_body", "rigid body: torque-free, constant torque, or PD law (3) to a fixed attitude",
     &check_rigid_body, &run_rigid_body},
}};

}  // namespace

std::span<const KindHandler> kinds() { return registry; }

const KindHandler& handler_for(const Document& doc) {
  const std::string kind = scenario_kind(doc);
  for (const KindHandler& h : registry) {
    if (h.name == kind) {
      return h;
    }
  }
  std::string known;
  for (const KindHandler& h : registry) {
    known += (known.empty() ? "" : ", ") + std::string(h.name);
  }
  TableReader(doc).fail("kind", "unknown scenario kind '" + kind + "' (known kinds: " + known + ")");
}

}  // namespace attiguard::scenario
