// Scenario kind `reach` (docs/scenario-format.md, section "reach").

#include "attiguard/scenario/read_reach.hpp"

#include <array>
#include <cmath>
#include <initializer_list>
#include <numbers>

#include "attiguard/reach/metrics.hpp"
#include "attiguard/scenario/common_tables.hpp"
#include "attiguard/scenario/messages.hpp"
#include "attiguard/scenario/table_reader.hpp"

namespace attiguard::scenario {

namespace {

std::shared_ptr<const reach::ClosedLoop> parse_system(const TableReader& sys, std::string& model) {
  static constexpr std::array<std::string_view, 4> models{"linear_omega", "free", "constant_torque",
                                                          "pd"};
  declare(sys, {"model", "matrix", "inertia", "torque_b", "kp", "kd", "reference"});
  model = sys.string("model", models);
  if (model == "linear_omega") {
    return std::make_shared<reach::LinearOmegaLoop>(sys.matrix3("matrix"));
  }
  const Eigen::Matrix3d J = sys.inertia("inertia");
  if (model == "free") return std::make_shared<reach::RigidBodyLoop>(J, Eigen::Vector3d::Zero());
  if (model == "constant_torque") {
    return std::make_shared<reach::RigidBodyLoop>(J, sys.vector3("torque_b"));
  }
  const double kp = sys.number("kp", NumberRule::positive());
  const double kd = sys.number("kd", NumberRule::positive());
  return std::make_shared<reach::PdLoop>(J, kp, kd, sys.rotation("reference"));
}

/// The entries of metric_P: 0 or normal numbers (docs/scenario-format.md, "reach"): a subnormal
/// entry made every derived ball subnormal, and reach.json a file the tool could not read back.
void check_metric_entries(const TableReader& init, const reach::Mat3& P) {
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (P(i, j) != 0.0 && std::fpclassify(P(i, j)) == FP_SUBNORMAL) {
        init.fail("metric_P", "entry [" + std::to_string(i) + "][" + std::to_string(j) + "] = " +
                                  detail::format_number(P(i, j)) +
                                  " is subnormal: each entry must be 0 or at least 2.2250738585072014e-308 in "
                                  "magnitude (P_0 of Algorithm 1; scale the metric instead)");
      }
    }
  }
}

/// [initial]: the initial set B_I(R0, a) × B_I(ω0, b) and P_0 [ConReach Alg. 1].
void parse_initial(const TableReader& root, reach::InitialSet& initial) {
  const TableReader init = root.table("initial");
  declare(init, {"attitude", "attitude_radius", "omega_b", "omega_radius", "metric_P"});
  if (init.has("attitude")) initial.R0 = init.rotation("attitude");
  initial.attitude_radius = init.number("attitude_radius", {0.0, std::numbers::pi, false, true});
  initial.omega0 = init.vector3("omega_b");
  initial.omega_radius = init.number("omega_radius", NumberRule::non_negative());
  if (init.has("metric_P")) {
    initial.P0 = init.matrix3("metric_P");
    check_metric_entries(init, initial.P0);
    if (!reach::is_spd(initial.P0)) {
      init.fail("metric_P", "must be symmetric positive definite (P_0 of Algorithm 1)");
    }
  }
  if (initial.attitude_radius + initial.omega_radius <= 0.0) {
    init.fail("omega_radius", "attitude_radius and omega_radius must not both be 0");
  }
}

/// The rate selection's keys of [reach] are the product metric's only (the coupled metric
/// chooses its rate itself, docs/reach.md "Rate selection"), each mode's own; reads rate_mode.
void check_rate_keys(const TableReader& r, bool attitude_dependent, reach::ConReachSettings& s) {
  const bool product = s.metric == reach::MetricKind::product;
  const std::string coupled_note =
      "only used by the product metric's rate selection (metric = \"product\"); the coupled "
      "metric chooses its rate itself (docs/reach.md, \"Rate selection\")";
  r.used_only_if("rate_mode", product, coupled_note);
  r.used_only_if("rate_step", product, coupled_note);
  s.mode = enum_or(r, "rate_mode", reach::kRateModeNames, reach::RateMode::line_search);
  const bool line_search = product && s.mode == reach::RateMode::line_search;
  const std::string line_search_note = product ? "only used by rate_mode = \"line_search\"" : coupled_note;
  r.used_only_if("line_search_steps", line_search, line_search_note);
  r.used_only_if("min_diagonal", line_search, line_search_note);
  r.used_only_if("min_enclosure_candidates", product && !line_search,
                 product ? "only used by rate_mode = \"min_enclosure\"" : coupled_note);
  r.used_only_if("attitude_floor_ratio", product && attitude_dependent,
                 product ? "only used when the loop's LMI depends on the attitude (a PD loop)"
                         : coupled_note);
}

/// [reach]: the ConReach settings (docs/scenario-format.md, section "reach").
void parse_settings(const TableReader& root, const reach::ClosedLoop& loop, reach::ConReachSettings& s) {
  const TableReader r = root.table("reach");
  declare(r, {"horizon", "steps", "rate_mode", "line_search_steps", "rate_step", "min_diagonal",
              "substeps", "integrator_step", "attitude_floor_ratio", "min_enclosure_candidates",
              "metric", "rigour", "max_bisections", "sdp_solver"});
  s.horizon = r.number("horizon", NumberRule::positive());
  // Without `steps` the analysis chooses its step lengths (docs/reach.md, "Adaptive steps").
  s.adaptive = !r.has("steps");
  s.steps = s.adaptive ? 1 : static_cast<int>(r.integer("steps", 1, 100000));
  s.max_bisections = static_cast<int>(r.integer_or("max_bisections", 6, 0, 30));
  // Default (docs/reach.md, "Coupled metrics"): coupled where the closed loop feeds the
  // attitude back (its LMI depends on R: the R–ω coupling is what makes it contract), the
  // paper's product metric otherwise.
  s.metric = enum_or(r, "metric", reach::kMetricNames,
                     loop.lmi_depends_on_attitude() ? reach::MetricKind::coupled
                                                    : reach::MetricKind::product);
  check_rate_keys(r, loop.lmi_depends_on_attitude(), s);
  s.rigour = enum_or(r, "rigour", reach::kRigourNames, reach::Rigour::rigorous);
  s.sdp.sdp.solver = enum_or(r, "sdp_solver", reach::kSdpSolverNames, reach::kDefaultSdpSolver);
  s.line_search_steps = static_cast<int>(r.integer_or("line_search_steps", 3, 1, 1000));
  s.rate_step = r.number_or("rate_step", 0.01, NumberRule::positive());
  s.min_diagonal = r.number_or("min_diagonal", 0.01, NumberRule::non_negative());
  s.substeps = static_cast<int>(r.integer_or("substeps", 10, 1, 10000));
  // Adaptive steps: no integrator_step means 0.02/λ of the loop (conreach.hpp); the fixed grid
  // keeps its 1 ms default.
  s.integrator_step = r.number_or("integrator_step", s.adaptive ? 0.0 : 1e-3, NumberRule::positive());
  s.attitude_floor_ratio = r.number_or("attitude_floor_ratio", 0.5, {0.0, 1.0, true, false});
  s.min_enclosure_candidates =
      static_cast<int>(r.integer_or("min_enclosure_candidates", 30, 1, 1000));
  if (s.adaptive) {
    if (s.integrator_step > s.horizon) r.fail("integrator_step", "integrator_step must not exceed the horizon");
    if (s.integrator_step > 0.0) {
      require_countable(r, "integrator_step", s.integrator_step, s.horizon, kMaxRunSteps,
                        "integrator steps of the nominal");
    }
    return;
  }
  if (s.integrator_step > s.horizon / s.steps / s.substeps) {
    r.fail(r.has("integrator_step") ? "integrator_step" : "substeps",
           "integrator_step must not exceed horizon/(steps*substeps)");
  }
  require_countable(r, "integrator_step", s.integrator_step, s.horizon, kMaxRunSteps,
                    "integrator steps of the nominal");
}

/// [partition]: cells per axis and threads, within the cell budget.
void parse_partition(const TableReader& root, int steps, reach::ReachScenario& sc) {
  if (const auto part = root.optional_table("partition")) {
    declare(*part, {"attitude_cells", "omega_cells", "threads", "split", "max_cell_steps", "max_seconds"});
    sc.attitude_cells = static_cast<int>(part->integer_or("attitude_cells", 1, 1, 50));
    sc.omega_cells = static_cast<int>(part->integer_or("omega_cells", 1, 1, 50));
    sc.threads = static_cast<int>(part->integer_or("threads", 0, 0, 256));
    sc.split.enabled = part->boolean_or("split", true);
    sc.split.max_cell_steps = part->integer_or("max_cell_steps", sc.split.max_cell_steps, 1, 100000000);
    sc.split.max_seconds = part->number_or("max_seconds", sc.split.max_seconds, NumberRule::positive());
    require_cell_budget(*part, part->has("omega_cells") ? "omega_cells" : "attitude_cells", sc.attitude_cells, sc.omega_cells, steps);
  }
}

/// [soundness]: samples, seed, step. Each soundness sample (and each adversarial evaluation)
/// integrates the horizon with soundness.step: the run-step work limit per sample, and over all
/// samples (docs/scenario-format.md, "reach", [soundness]; docs/errors.md, "Work too large").
void parse_soundness(const TableReader& root, double horizon, reach::SoundnessSettings& soundness) {
  if (const auto snd = root.optional_table("soundness")) {
    declare(*snd, {"samples", "seed", "step"});
    soundness.samples = snd->integer_or("samples", 10000, 0, 100000000);
    soundness.seed = static_cast<std::uint64_t>(snd->integer_or("seed", 1, 0, 1L << 62));
    soundness.step = snd->number_or("step", 0.01, NumberRule::positive());
  }
  if (const auto snd = root.optional_table("soundness")) {
    require_countable(*snd, "step", soundness.step, horizon, kMaxRunSteps,
                      "integrator steps of each soundness sample");
    const double total = static_cast<double>(soundness.samples) * (horizon / soundness.step);
    if (!(total <= limit_value(kMaxRunSteps))) {
      snd->fail(snd->has("step") ? "step" : "samples",
                "samples x horizon/step = " + detail::format_number(std::ceil(total)) +
                    " integrator steps of the soundness check (at most " +
                    detail::format_number(limit_value(kMaxRunSteps)) + ", or raise the limit with " +
                    std::string(limit_flag(kMaxRunSteps)) +
                    " N): a check that size does not finish in reasonable time; use fewer samples "
                    "or a larger step");
    }
  }
}

/// One [[safety.cones]] entry: the cone schema of kinds pet_erg and mission (common_tables.hpp)
/// plus a name; the governor's field keys (delta_offset, ...) are not part of a safety cone.
reach::PointingCone parse_safety_cone(const TableReader& c, int idx) {
  declare(c, {"name"});
  reach::PointingCone cone;
  cone.name = c.string_or("name", "cone" + std::to_string(idx));
  const ConeGeometry g = read_cone_geometry(c);
  cone.keep_out = g.keep_out;
  cone.axis_b = g.axis_b;
  cone.direction_i = g.direction_i;
  cone.half_angle = g.half_angle;
  return cone;
}

/// [safety]: the cones and the ω bounds the reach tube must keep.
void parse_safety(const TableReader& root, reach::SafetySpec& safety) {
  if (const auto saf = root.optional_table("safety")) {
    declare(*saf, {"cones", "omega_abs_max", "omega_norm_max"});
    if (saf->has("cones")) {
      int idx = 0;
      for (const TableReader& c : saf->array_of_tables("cones")) {
        safety.cones.push_back(parse_safety_cone(c, idx++));
      }
    }
    if (saf->has("omega_abs_max")) {
      const Eigen::Vector3d m = saf->vector3("omega_abs_max");
      if (!(m.array() > 0.0).all()) saf->fail("omega_abs_max", "every bound must be > 0");
      safety.omega_abs_max = m;
    }
    if (saf->has("omega_norm_max")) {
      safety.omega_norm_max = saf->number("omega_norm_max", NumberRule::positive());
    }
  }
}

/// [output]: boundary points per ball and the sampled trajectories kept for plots.
void parse_output(const TableReader& root, reach::ReachScenario& sc) {
  if (const auto out = root.optional_table("output")) {
    declare(*out, {"boundary_points", "plot_trajectories"});
    sc.boundary_points = static_cast<int>(out->integer_or("boundary_points", 200, 0, 100000));
    sc.soundness.keep = static_cast<int>(out->integer_or("plot_trajectories", 20, 0, 10000));
  }
}

}  // namespace

reach::ReachScenario parse_reach(const Document& doc) {
  reach::ReachScenario sc;
  const TableReader root(doc);
  declare(root, {"kind", "name", "description", "system", "initial", "reach", "partition",
                 "soundness", "safety", "output"});
  sc.name = read_header(root, doc, "reach", "reach");
  sc.loop = parse_system(root.table("system"), sc.model);
  parse_initial(root, sc.initial);
  parse_settings(root, *sc.loop, sc.settings);
  parse_partition(root, sc.settings.adaptive ? 1 : sc.settings.steps, sc);
  parse_soundness(root, sc.settings.horizon, sc.soundness);
  sc.soundness.threads = sc.threads;
  parse_safety(root, sc.safety);
  parse_output(root, sc);
  root.finish();
  return sc;
}

}  // namespace attiguard::scenario
