#include "attiguard/scenario/kinds.hpp"

#include <array>
#include <chrono>
#include <string>

#include "attiguard/core/errors.hpp"
#include "attiguard/scenario/mission_scenario.hpp"
#include "attiguard/scenario/pet_erg_scenario.hpp"
#include "attiguard/scenario/reach_scenario.hpp"
#include "attiguard/scenario/rigid_body_scenario.hpp"
#include "attiguard/scenario/table_reader.hpp"
#include "attiguard/scenario/waypoint_scenario.hpp"
#include "attiguard/sim/mission_run.hpp"
#include "attiguard/sim/pet_erg_run.hpp"
#include "attiguard/sim/rigid_body_run.hpp"
#include "attiguard/sim/waypoint_run.hpp"

namespace attiguard::scenario {

namespace {

void check_rigid_body(const Document& doc) { (void)parse_rigid_body(doc); }

nlohmann::json run_rigid_body(const Document& doc, const RunOptions& options) {
  return sim::run_rigid_body(parse_rigid_body(doc), options.out_dir);
}

void check_pet_erg(const Document& doc) { (void)parse_pet_erg(doc); }

nlohmann::json run_pet_erg(const Document& doc, const RunOptions& options) {
  if (!options.write_files) {  // campaigns: the summary only, no file
    const auto start = std::chrono::steady_clock::now();
    const PetErgScenario sc = parse_pet_erg(doc);
    const sim::PetErgResult result = sim::simulate_pet_erg(sc);
    return sim::pet_erg_summary(
        sc, result,
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return sim::run_pet_erg(parse_pet_erg(doc), options.out_dir);
}

void check_waypoint(const Document& doc) { (void)parse_waypoint(doc); }

nlohmann::json run_waypoint(const Document& doc, const RunOptions& options) {
  return sim::run_waypoint(parse_waypoint(doc), options.out_dir);
}

void check_mission(const Document& doc) { (void)parse_mission(doc); }

nlohmann::json run_mission(const Document& doc, const RunOptions& options) {
  return sim::run_mission(parse_mission(doc), options.out_dir);
}

void check_reach(const Document& doc) { (void)parse_reach(doc); }

// Reachability is an analysis, not a simulation: it has its own subcommand and outputs.
nlohmann::json run_reach(const Document& doc, const RunOptions&) {
  TableReader(doc).fail("kind", "scenario kind 'reach' is analysed with `attiguard reach " +
                                    doc.path.string() + " --out DIR`, not `attiguard run`");
}

constexpr std::array<KindHandler, 5> registry{{
    {"rigid_body", "rigid body: torque-free, constant torque, or PD law (3) to a fixed attitude",
     &check_rigid_body, &run_rigid_body},
    {"pet_erg",
     "constrained attitude control: PD law (3) with the PET-ERG (5)-(6), the ERG (4), or none",
     &check_pet_erg, &run_pet_erg},
    {"waypoint",
     "waypoint tracking with one main thruster, wheels and six RCT (align/accelerate/coast/flip/"
     "decelerate/fine state machine)",
     &check_waypoint, &run_waypoint},
    {"mission",
     "waypoint guidance through the PET-ERG: pointing cones and torque limit kept during the "
     "slews; also flies the unconstrained twin",
     &check_mission, &run_mission},
    {"reach",
     "ConReach contraction-based reachability and safety verification (use `attiguard reach`)",
     &check_reach, &run_reach},
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
