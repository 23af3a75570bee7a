// A downstream user's PET-ERG run with robust margins and reaction wheels built from plain values
// against the installed attiguard::attiguard, without a scenario file: the values of the nominal
// case of examples/pet_erg_robust_campaign.toml (its [dispersions] left out) written into a
// sim::PetErgScenario, the governor's design by governor::design (docs/pet-erg.md, sections
// 12-13), flown by sim::simulate_pet_erg. Exit 0 when its summary is the one of the example file
// itself (scenario::parse_pet_erg of its nominal document, which `attiguard campaign` flies as
// the nominal case) in every figure, exactly; exit 1 with the differing figures otherwise.
// argv[1]: the example file.
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include <nlohmann/json.hpp>

#include "attiguard/governor/governor_design.hpp"
#include "attiguard/lie/so3.hpp"
#include "attiguard/scenario/dispersion.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/read_pet_erg.hpp"
#include "attiguard/sim/pet_erg_run.hpp"
#include "attiguard/sim/pet_erg_scenario.hpp"

namespace ag = attiguard;
using ag::lie::Mat3;
using ag::lie::Vec3;

namespace {

/// A direction as a scenario file gives it: normalised.
Vec3 unit(const Vec3& v) { return v / v.norm(); }

constexpr double kDegree = std::numbers::pi / 180.0;

ag::sim::PetErgScenario plain_scenario() {
  ag::sim::PetErgScenario sc;
  sc.name = "pet_erg_robust_campaign";
  ag::governor::GovernorParams& p = sc.params;  // governor, [body], [control], [erg]
  p.mode = ag::governor::GovernorMode::pet;
  p.J << 120.0, 5.0, -3.0, 5.0, 90.0, 2.0, -3.0, 2.0, 150.0;
  p.gains = {0.5, 6.0};
  p.tau_max = 1.0;
  p.kappa = 20.0;
  p.Ts = 1.0;
  sc.control_period = 0.1;
  sc.margins = ag::governor::Margins::robust;
  sc.robust_reference_step = 0.002;
  sc.omega0_b = Vec3(0.001, -0.001, 0.0005);
  sc.desired = ag::governor::ReferenceSchedule(ag::lie::exp(120.0 * std::numbers::pi / 180.0 * Vec3::UnitZ()));
  const Vec3 x = Vec3::UnitX();
  sc.cones = {ag::governor::keep_out_cone(x, unit({0.49, 0.85, 0.17}), 40.0 * kDegree, 0.002, 0.05, 0.1),
              ag::governor::keep_out_cone(x, unit({-0.81, 0.47, -0.34}), 15.0 * kDegree, 0.002, 0.05, 0.1),
              ag::governor::keep_in_cone(Vec3::UnitZ(), Vec3::UnitZ(), 60.0 * kDegree)};
  for (const Vec3& a : {Vec3(0.577382, 0.577382, 0.577288), Vec3(-0.577382, 0.577382, 0.577288),
                        Vec3(-0.577382, -0.577382, 0.577288), Vec3(0.577382, -0.577382, 0.577288)}) {
    sc.wheels.push_back({unit(a), 0.1, 6.0, 0.0});
  }
  ag::sim::PetErgImperfections& im = sc.imperfections;
  im.disturbance.kind = ag::dynamics::DisturbanceKind::adversarial;
  im.disturbance.bound = 0.003;
  im.disturbance.hold = sc.control_period;
  im.adversary.weight = 0.5;
  im.sensor.attitude_bias_b = Vec3(0.0002, -0.0002, 0.0001);
  im.sensor.attitude_noise = 0.0002;
  im.sensor.rate_bias_b = Vec3(0.00001, 0.0, -0.00001);
  im.sensor.rate_noise = 0.00002;
  im.attitude_bias_bound = 0.0215;
  im.rate_bias_bound = im.sensor.rate_bias_b.stableNorm();
  im.delay_periods = 1;
  im.torque_quantum = 0.001;
  sc.duration = 1500.0;
  sc.output_interval = 5.0;
  sc.integrator.step = 0.1;
  sc.convergence_tolerance = 1e-3;
  return sc;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: robust_design EXAMPLE.toml\n");
    return 2;
  }
  const ag::sim::PetErgScenario plain = plain_scenario();
  const ag::governor::GovernorDesign design = ag::sim::design_governor(plain);
  const nlohmann::json mine = ag::sim::pet_erg_summary(plain, ag::sim::simulate_pet_erg(plain));
  const ag::sim::PetErgScenario filed =
      ag::scenario::parse_pet_erg(ag::scenario::nominal_document(ag::scenario::load_document(argv[1])));
  const nlohmann::json theirs = ag::sim::pet_erg_summary(filed, ag::sim::simulate_pet_erg(filed));
  int differing = 0;
  for (const auto& [key, value] : theirs.items()) {
    if (!mine.contains(key) || mine[key] != value) {
      std::printf("differs: %s: %s vs %s\n", key.c_str(), mine.value(key, nlohmann::json()).dump().c_str(),
                  value.dump().c_str());
      ++differing;
    }
  }
  const bool same_keys = mine.size() == theirs.size();
  std::printf("robust design from plain values: tau_max reduced %.6g N m, wheel Gamma_d %.6g -> %.6g, "
              "Gamma_min %.6g; final error %.3e, min margin %.6f, %ld governor updates of %ld samples; "
              "%d of %zu figures differ from the file's run\n",
              design.tau_max_reduced, design.wheels.gamma_d, design.wheel_gamma_d_reduced,
              design.params.robust->gamma_min, mine["final_attitude_error"].get<double>(),
              mine["min_pointing_margin"].get<double>(), mine["samples_updating"].get<long>(),
              mine["samples"].get<long>(), differing, theirs.size());
  const bool ok = differing == 0 && same_keys && mine["margins"] == "robust" &&
                  mine["constraints_satisfied"] == true;
  return ok ? 0 : 1;
}
