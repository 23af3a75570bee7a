// Gain search of a pet_erg scenario (tune_search.hpp; docs/pet-erg.md, section "Tuning").

#include "attiguard/app/tune_search.hpp"

#include <algorithm>
#include <cmath>
#include <charconv>
#include <numbers>

#include "attiguard/app/kinds.hpp"
#include "attiguard/app/tune_batch.hpp"
#include "attiguard/campaign/seed.hpp"
#include "attiguard/core/errors.hpp"
#include "attiguard/core/one_line.hpp"
#include "attiguard/scenario/document_edit.hpp"
#include "attiguard/governor/default_gains.hpp"
#include "attiguard/scenario/read_pet_erg.hpp"
#include "attiguard/sim/planned_run.hpp"

namespace attiguard::app {

namespace {

std::optional<double> number_field(const nlohmann::json& summary, const char* key) {
  const auto it = summary.find(key);
  if (it == summary.end() || !it->is_number()) return std::nullopt;
  return it->get<double>();
}

/// Latin hypercube of n points in the log box: one point per stratum of each axis, strata
/// permuted independently (Fisher–Yates with `rng`).
std::vector<std::vector<double>> latin_hypercube(const std::vector<TuneParameter>& p, long n,
                                                 campaign::Rng& rng) {
  std::vector<std::vector<double>> pts(static_cast<std::size_t>(n), std::vector<double>(p.size()));
  for (std::size_t d = 0; d < p.size(); ++d) {
    std::vector<long> perm(static_cast<std::size_t>(n));
    for (long i = 0; i < n; ++i) perm[static_cast<std::size_t>(i)] = i;
    for (long i = n - 1; i > 0; --i) {
      const auto j = static_cast<long>(rng.uniform01() * static_cast<double>(i + 1));
      std::swap(perm[static_cast<std::size_t>(i)], perm[static_cast<std::size_t>(std::min(j, i))]);
    }
    const double lo = std::log(p[d].min), hi = std::log(p[d].max);
    for (long i = 0; i < n; ++i) {
      const double u = (static_cast<double>(perm[static_cast<std::size_t>(i)]) + rng.uniform01()) /
                       static_cast<double>(n);
      pts[static_cast<std::size_t>(i)][d] = std::exp(lo + u * (hi - lo));
    }
  }
  return pts;
}

/// A point within `radius` (fraction of each log range) of `centre`, clamped to the box.
std::vector<double> perturb(const std::vector<TuneParameter>& p, const std::vector<double>& centre,
                            double radius, campaign::Rng& rng) {
  std::vector<double> x(p.size());
  for (std::size_t d = 0; d < p.size(); ++d) {
    const double lo = std::log(p[d].min), hi = std::log(p[d].max);
    const double v = std::log(centre[d]) + radius * (hi - lo) * rng.uniform(-1.0, 1.0);
    x[d] = std::exp(std::clamp(v, lo, hi));
  }
  return x;
}

bool faster(const TunePoint& a, const std::optional<std::size_t>& best,
            const std::vector<TunePoint>& points) {
  return a.admissible() && (!best || *a.convergence_time < *points[*best].convergence_time);
}

nlohmann::json point_json(const std::vector<TuneParameter>& parameters, const TunePoint& p) {
  nlohmann::json j;
  j["index"] = p.index;
  j["phase"] = p.phase;
  nlohmann::json values = nlohmann::json::object();
  for (std::size_t d = 0; d < parameters.size(); ++d) values[parameters[d].key] = p.values[d];
  j["values"] = values;
  j["status"] = p.status;
  j["outcome"] = p.outcome.empty() ? nlohmann::json(nullptr) : nlohmann::json(p.outcome);
  j["reason"] = p.reason;
  j["violations"] = p.violations;
  j["admissible"] = p.admissible();
  j["convergence_time"] = p.convergence_time ? nlohmann::json(*p.convergence_time) : nlohmann::json(nullptr);
  j["convergence_time_over_bang_bang"] = p.ratio ? nlohmann::json(*p.ratio) : nlohmann::json(nullptr);
  return j;
}

}  // namespace

namespace {

/// governor = "planned": k_R, k_Ω, the plan's headroom and cone margin around the values the
/// planned mode derives from the craft alone (the file's kp, kd, [plan] values set aside).
std::vector<TuneParameter> planned_tune_parameters(const sim::PetErgScenario& given) {
  sim::PetErgScenario sc = given;
  sc.derived.kp_derived = sc.derived.kd_derived = true;
  sc.plan.torque_headroom_given = sc.plan.cone_margin_given = false;
  const sim::PlannedFigures f = sim::planned_setup(sc).figures;
  const PlannedTuneSpaceConstants k;
  const double margin_deg = f.cone_margin * 180.0 / std::numbers::pi;
  return {{"control.kp", f.gains.k_R / k.stiffness, f.gains.k_R * k.stiffness},
          {"control.kd", f.gains.k_Omega / k.damping, f.gains.k_Omega * k.damping},
          {"plan.torque_headroom", std::max(0.01, f.torque_headroom / k.headroom),
           std::min(0.6, f.torque_headroom * k.headroom)},
          {"plan.cone_margin_deg", margin_deg / k.margin, std::min(20.0, margin_deg * k.margin)}};
}

}  // namespace

std::vector<TuneParameter> default_tune_parameters(const scenario::Document& nominal) {
  if (scenario::scenario_kind(nominal) != "pet_erg") {
    throw InputError(nominal.path.string() + ": kind: attiguard tune searches the gains of a "
                                             "pet_erg scenario, not '" + scenario::scenario_kind(nominal) + "'");
  }
  // Centred on the values derived from the craft alone (docs/pet-erg.md, section 8), whatever
  // the file gives, and scaled by them: each range is a fixed log-range of a dimensionless group.
  const sim::PetErgScenario sc = scenario::parse_pet_erg(nominal);
  if (sc.params.mode == governor::GovernorMode::planned) return planned_tune_parameters(sc);
  governor::DerivedGovernorValues d;
  try {
    d = governor::derive_governor_values(sim::craft_scales(sc), {});
  } catch (const SetupError& e) {
    throw InputError(nominal.path.string() + ": attiguard tune: " + e.what());
  }
  const TuneSpaceConstants k;
  // T_s no shorter than the flight loop's period (the trigger is evaluated at control instants).
  const double Ts_floor = std::max(d.Ts / k.sampling_period, sc.control_period);
  // κ and c_Γ are not searched by default: the convergence time is monotone in them and flat
  // beyond the derived values (docs/pet-erg.md, section 15), so their best would sit on a bound.
  return {{"control.kp", d.kp / k.stiffness, d.kp * k.stiffness},
          {"control.kd", d.kd / k.damping, d.kd * k.damping},
          {"erg.sampling_period", Ts_floor, std::max(Ts_floor, d.Ts * k.sampling_period)}};
}

std::vector<std::string> keys_on_bound(const std::vector<TuneParameter>& parameters,
                                       const std::vector<double>& values, double fraction) {
  std::vector<std::string> keys;
  for (std::size_t i = 0; i < parameters.size() && i < values.size(); ++i) {
    const TuneParameter& p = parameters[i];
    if (!(p.max > p.min)) continue;
    const double width = std::log(p.max / p.min);
    const double at = std::log(values[i] / p.min) / width;
    if (at <= fraction || at >= 1.0 - fraction) keys.push_back(p.key);
  }
  return keys;
}

TuneParameter parse_tune_range(const std::string& text) {
  const auto bad = [&](const std::string& why) {
    return InputError("--range '" + text + "': " + why + " (expected KEY=MIN:MAX, 0 < MIN <= MAX)");
  };
  const std::size_t eq = text.find('='), colon = text.find(':', eq == std::string::npos ? 0 : eq);
  if (eq == std::string::npos || eq == 0 || colon == std::string::npos) throw bad("malformed");
  TuneParameter p;
  p.key = text.substr(0, eq);
  const auto parse = [&](std::size_t from, std::size_t to, double& out) {
    const char* b = text.data() + from;
    const char* e = text.data() + to;
    const auto r = std::from_chars(b, e, out);
    if (r.ec != std::errc{} || r.ptr != e) throw bad("not a number");
  };
  parse(eq + 1, colon, p.min);
  parse(colon + 1, text.size(), p.max);
  if (!std::isfinite(p.min) || !std::isfinite(p.max) || !(p.min > 0.0) || !(p.min <= p.max)) {
    throw bad("bounds");
  }
  return p;
}

scenario::Document tune_candidate(const scenario::Document& nominal,
                                  const std::vector<TuneParameter>& parameters,
                                  const std::vector<double>& values) {
  scenario::Document d = nominal;
  for (std::size_t i = 0; i < parameters.size(); ++i) scenario::set_number(d, parameters[i].key, values[i]);
  return d;
}

TunePoint evaluate_candidate(const scenario::Document& nominal,
                             const std::vector<TuneParameter>& parameters,
                             const std::vector<double>& values, const std::filesystem::path& scratch) {
  TunePoint p;
  p.values = values;
  const KindHandler& handler = handler_for(nominal);
  scenario::Document doc;
  try {
    doc = tune_candidate(nominal, parameters, values);
    handler.check(doc);
  } catch (const std::exception& e) {
    p.status = "rejected";
    p.reason = one_line(e.what());
    return p;
  }
  nlohmann::json summary;
  try {
    RunOptions options;
    options.out_dir = scratch;
    options.write_files = false;
    summary = handler.run(doc, options);
  } catch (const std::exception& e) {
    p.status = "failed";
    p.reason = one_line(e.what());
    return p;
  }
  p.status = "ok";
  if (const auto it = summary.find("outcome"); it != summary.end() && it->is_string()) {
    p.outcome = it->get<std::string>();
  }
  if (const auto it = summary.find("outcome_reason"); it != summary.end() && it->is_string()) {
    p.reason = it->get<std::string>();
  }
  for (const auto& [key, value] : summary.items()) {
    if (value.is_boolean() && !value.get<bool>() && key.ends_with("_satisfied")) ++p.violations;
  }
  p.convergence_time = number_field(summary, "convergence_time");
  p.ratio = number_field(summary, "convergence_time_over_bang_bang");
  p.bang_bang_time = number_field(summary, "eigenaxis_bang_bang_time");
  return p;
}

namespace {

/// The settings and the scenario a search can run on: InputError naming what is not.
void check_tune_settings(const scenario::Document& nominal, const TuneSettings& s) {
  if (s.parameters.empty()) throw InputError("attiguard tune: no parameter to search");
  if (s.budget < 4) throw InputError("--budget: must be at least 4 runs");
  if (s.threads < 1) throw InputError("--threads: must be at least 1");
  if (s.batch < 1) throw InputError("--batch: must be at least 1");
  for (const TuneParameter& p : s.parameters) {
    if (!(p.min > 0.0) || !(p.min <= p.max) || !std::isfinite(p.max)) {
      throw InputError("attiguard tune: " + p.key + ": range must satisfy 0 < min <= max");
    }
  }
  if (scenario::scenario_kind(nominal) != "pet_erg") {
    throw InputError(nominal.path.string() + ": kind: attiguard tune searches the gains of a "
                                             "pet_erg scenario, not '" + scenario::scenario_kind(nominal) + "'");
  }
  // Every key can be set (a key of a table the scenario does not have is an input error).
  std::vector<double> lows;
  for (const TuneParameter& p : s.parameters) lows.push_back(p.min);
  (void)tune_candidate(nominal, s.parameters, lows);
}

/// Appends the evaluated `batch` to the search's points in `phase`; whether it holds a new best.
bool append_points(TuneResult& r, std::vector<TunePoint> batch, const char* phase) {
  bool improved = false;
  for (TunePoint& p : batch) {
    p.index = static_cast<long>(r.points.size());
    p.phase = phase;
    if (faster(p, r.best, r.points)) {
      r.best = r.points.size();
      improved = true;
    }
    r.points.push_back(std::move(p));
  }
  return improved;
}

/// Takes the points of `batch` that were not evaluated (status "stopped": the search was
/// stopped first) out of it; whether there was one. Every rank sees the same batch
/// (tune_batch.hpp), so every rank takes the same decision.
bool drop_stopped(std::vector<TunePoint>& batch) {
  const auto first = std::remove_if(batch.begin(), batch.end(),
                                    [](const TunePoint& p) { return p.status == "stopped"; });
  const bool any = first != batch.end();
  batch.erase(first, batch.end());
  return any;
}

/// The next `n` candidates: perturbed around the best point within `radius`, or (nothing
/// admissible yet) a new Latin hypercube, to keep exploring.
std::vector<std::vector<double>> next_candidates(const TuneSettings& s, const TuneResult& r, long n,
                                                 double radius, campaign::Rng& rng) {
  if (!r.best) return latin_hypercube(s.parameters, n, rng);
  std::vector<std::vector<double>> batch;
  for (long i = 0; i < n; ++i) batch.push_back(perturb(s.parameters, r.points[*r.best].values, radius, rng));
  return batch;
}

}  // namespace

TuneResult tune_search(const scenario::Document& nominal, const TuneSettings& s) {
  check_tune_settings(nominal, s);
  // Every rank runs this same search on the same points (tune_batch.hpp): the same draws from
  // the same stream, the same decisions; only the evaluation of a batch is split.
  const std::filesystem::path scratch = s.scratch / ("rank" + std::to_string(s.world.rank));
  const auto evaluate = [&](const std::vector<TuneParameter>& parameters,
                            const std::vector<std::vector<double>>& candidates) {
    return evaluate_tune_batch(nominal, parameters, candidates, s.threads, scratch, s.world, s.stop);
  };
  TuneResult r;
  campaign::Rng rng(campaign::run_seed(s.seed, 0));
  // The scenario as given (its own gains), for comparison; not a search point.
  r.nominal = std::move(evaluate({}, {std::vector<double>{}}).front());
  r.nominal.phase = "nominal";
  r.stopped = r.nominal.status == "stopped";
  for (const TuneParameter& p : s.parameters) {
    r.nominal.values.push_back(scenario::number_at(nominal, p.key).value_or(std::nan("")));
  }
  const long samples = std::max(1L, s.budget / 2);
  if (!r.stopped) {
    std::vector<TunePoint> first = evaluate(s.parameters, latin_hypercube(s.parameters, samples, rng));
    r.stopped = drop_stopped(first);
    append_points(r, std::move(first), "sample");
  }
  double radius = 0.25;
  const long batch_size = s.batch;  // not the worker count: the same points whatever N and T
  // A stop (TuneSettings::stop) ends the search after the batch in hand, with its points so far.
  while (!r.stopped && static_cast<long>(r.points.size()) < s.budget) {
    const long n = std::min(batch_size, s.budget - static_cast<long>(r.points.size()));
    const char* phase = r.best ? "refine" : "sample";
    const std::vector<std::vector<double>> batch = next_candidates(s, r, n, radius, rng);
    std::vector<TunePoint> evaluated = evaluate(s.parameters, batch);
    r.stopped = drop_stopped(evaluated);
    const bool improved = append_points(r, std::move(evaluated), phase);
    // Shrink the neighbourhood after a batch without progress; once it is tiny, restart it
    // wide around the best (escapes a narrow valley without losing the best point).
    if (!improved) radius *= 0.7;
    if (radius < 0.01) radius = 0.25;
  }
  r.eigenaxis_bang_bang_time = r.nominal.bang_bang_time;  // a property of the slew, not the gains
  for (const TunePoint& p : r.points) {
    if (!r.eigenaxis_bang_bang_time) r.eigenaxis_bang_bang_time = p.bang_bang_time;
  }
  return r;
}

nlohmann::json tune_json(const TuneSettings& s, const TuneResult& r) {
  nlohmann::json j;
  nlohmann::json space = nlohmann::json::array();
  for (const TuneParameter& p : s.parameters) space.push_back({{"key", p.key}, {"min", p.min}, {"max", p.max}});
  j["parameters"] = space;
  j["budget"] = s.budget;
  j["seed"] = s.seed;
  j["batch"] = s.batch;
  j["search"] = "Latin hypercube (log-uniform) of budget/2 points, then "
                "batches of `batch` points perturbed around the fastest admissible point (radius 0.25 of each log range, x0.7 after a batch without progress, back to 0.25 below 0.01)";
  long admissible = 0;
  for (const TunePoint& p : r.points) admissible += p.admissible() ? 1 : 0;
  j["evaluated"] = r.points.size();
  j["admissible"] = admissible;
  j["eigenaxis_bang_bang_time"] = r.eigenaxis_bang_bang_time ? nlohmann::json(*r.eigenaxis_bang_bang_time) : nlohmann::json(nullptr);
  j["nominal"] = point_json(s.parameters, r.nominal);
  if (r.best) {
    const TunePoint& b = r.points[*r.best];
    j["outcome"] = "found";
    j["best"] = point_json(s.parameters, b);
    j["best_on_bound"] = keys_on_bound(s.parameters, b.values);
    j["convergence_time"] = *b.convergence_time;
    j["convergence_time_over_bang_bang"] = b.ratio ? nlohmann::json(*b.ratio) : nlohmann::json(nullptr);
  } else {
    j["outcome"] = "none_converged";
    j["outcome_reason"] = "none of the " + std::to_string(r.points.size()) +
                          " evaluated points converged with every constraint kept";
    j["best"] = nullptr;
  }
  if (r.stopped) {  // an honest outcome: the budget was not spent (docs/pet-erg.md, section 15)
    j["stopped"] = true;
    j["outcome"] = "interrupted";
    j["outcome_reason"] = "the search was stopped after " + std::to_string(r.points.size()) + " of " +
                          std::to_string(s.budget) + " runs" +
                          (r.best ? std::string("; best: the fastest admissible point so far")
                                  : std::string("; no admissible point so far"));
  }
  nlohmann::json points = nlohmann::json::array();
  for (const TunePoint& p : r.points) points.push_back(point_json(s.parameters, p));
  j["points"] = points;
  return j;
}

}  // namespace attiguard::app
