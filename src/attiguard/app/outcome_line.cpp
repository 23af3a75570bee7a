/// @file outcome_line.cpp
/// The one-line outcomes of docs/conventions.md, "Outcome line".

#include "attiguard/app/outcome_line.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <optional>
#include <string_view>
#include <utility>

#include "attiguard/campaign/aggregation.hpp"
#include "attiguard/core/four_digits.hpp"
#include "attiguard/core/one_line.hpp"

namespace attiguard::app {

namespace {

using nlohmann::json;

/// The number at `key` of `j`, if `j` is an object holding a finite number there.
std::optional<double> number(const json& j, std::string_view key) {
  if (!j.is_object()) return std::nullopt;
  const auto it = j.find(key);
  if (it == j.end() || !it->is_number()) return std::nullopt;
  const double v = it->get<double>();
  if (!std::isfinite(v)) return std::nullopt;
  return v;
}

/// The string at `key` of `j`, or `fallback`.
std::string text(const json& j, std::string_view key, std::string_view fallback = "") {
  if (j.is_object()) {
    const auto it = j.find(key);
    if (it != j.end() && it->is_string()) return it->get<std::string>();
  }
  return std::string(fallback);
}

/// The boolean at `key` of `j`, if it is one.
std::optional<bool> flag(const json& j, std::string_view key) {
  if (!j.is_object()) return std::nullopt;
  const auto it = j.find(key);
  if (it == j.end() || !it->is_boolean()) return std::nullopt;
  return it->get<bool>();
}

/// The integer at `key` of `j`, or 0 (counts of runs and points).
long count(const json& j, std::string_view key) {
  if (!j.is_object()) return 0;
  const auto it = j.find(key);
  return it != j.end() && it->is_number_integer() ? it->get<long>() : 0;
}

/// A figure for humans: 4 significant digits (core/four_digits.hpp).
std::string fig(double v) { return four_digits(v); }

/// The line being built: `outcome: WORD`, then "; "-separated parts.
class Line {
 public:
  explicit Line(std::string_view word) : line_("outcome: ") { line_ += word; }
  /// Appends " (detail)" right after the word (or the last part); nothing when empty.
  Line& detail(std::string_view d) {
    if (!d.empty()) (line_ += " (") += one_line(std::string(d)) + ")";
    return *this;
  }
  /// A part "; text" (line breaks in it become spaces); nothing when empty.
  Line& part(std::string_view t) {
    if (!t.empty()) (line_ += "; ") += one_line(std::string(t));
    return *this;
  }
  /// A part "label value unit" when the value is present.
  Line& part(std::string_view label, std::optional<double> v, std::string_view unit = "") {
    if (!v) return *this;
    std::string t(label);
    t += ' ';
    t += fig(*v);
    if (!unit.empty()) (t += ' ') += unit;
    return part(t);
  }
  [[nodiscard]] std::string str() const { return line_; }

 private:
  std::string line_;
};

/// "constraints kept" / "constraint VIOLATED" from a `constraints_satisfied` flag.
void constraints_part(Line& line, const json& summary) {
  if (const auto ok = flag(summary, "constraints_satisfied")) {
    line.part(*ok ? "constraints kept" : "constraint VIOLATED");
  }
}

/// The largest `key` over the objects of the array `array_key` of `j`.
std::optional<double> max_over(const json& j, std::string_view array_key, std::string_view key) {
  if (!j.is_object()) return std::nullopt;
  const auto it = j.find(array_key);
  if (it == j.end() || !it->is_array()) return std::nullopt;
  std::optional<double> best;
  for (const json& item : *it) {
    if (const auto v = number(item, key)) best = best ? std::max(*best, *v) : *v;
  }
  return best;
}

/// The waypoint figures shared by kinds waypoint and mission: time, Δv, worst arrival error.
void waypoint_parts(Line& line, const json& summary, std::optional<double> worst_arrival) {
  line.part("time", number(summary, "total_time"), "s");
  line.part("delta-v", number(summary, "total_delta_v"), "m/s");
  line.part("worst arrival error", worst_arrival, "m");
}

/// "saddle tie-break around cone I at t = T s" (or "N saddle tie-breaks, the first around …")
/// when summary.json counts any (docs/pet-erg.md, section 4, "Saddles: the tie-break").
std::string tie_break_detail(const json& summary) {
  const long n = count(summary, "saddle_tie_breaks");
  if (n <= 0) return {};
  std::string d = n == 1 ? "saddle tie-break" : std::to_string(n) + " saddle tie-breaks, the first";
  const auto it = summary.find("tie_break_cones");
  if (it != summary.end() && it->is_array() && !it->empty() && it->front().is_number_integer()) {
    d += " around cone " + std::to_string(it->front().get<long>());
  }
  if (const auto t = number(summary, "first_tie_break_time")) d += " at t = " + fig(*t) + " s";
  return d;
}

}  // namespace

/// governor = "planned": the convergence against the plan's duration and how long the clock
/// was held (docs/pet-erg.md, section 16.2).
void planned_parts(Line& line, const json& summary) {
  const auto it = summary.find("planned");
  if (it == summary.end() || !it->is_object()) return;
  const auto over = number(*it, "convergence_time_over_plan");
  const auto plan = it->find("plan");
  const auto T_p = plan != it->end() ? number(*plan, "duration") : std::nullopt;
  if (over && T_p) line.part(fig(*over) + "x the plan's " + fig(*T_p) + " s");
  line.part("clock held", number(*it, "time_held"), "s");
}

std::string pet_erg_outcome_line(const json& summary) {
  const std::string word = text(summary, "outcome", "unknown");
  Line line(word);
  line.detail(tie_break_detail(summary));
  const auto t_conv = number(summary, "convergence_time");
  const auto ratio = number(summary, "convergence_time_over_bang_bang");
  const auto t_bb = number(summary, "eigenaxis_bang_bang_time");
  if (t_conv) {
    std::string t = "at " + fig(*t_conv) + " s";
    if (ratio && t_bb) t += " = " + fig(*ratio) + "x the eigenaxis bang-bang time " + fig(*t_bb) + " s";
    const auto wheels_ratio = number(summary, "convergence_time_over_wheels_bang_bang");
    const auto t_wheels = number(summary, "eigenaxis_bang_bang_time_wheels");
    if (wheels_ratio && t_wheels) t += " (" + fig(*wheels_ratio) + "x the wheels' " + fig(*t_wheels) + " s)";
    line.part(t);
    planned_parts(line, summary);
  } else if (const auto d = number(summary, "duration")) {
    line.part("not converged by " + fig(*d) + " s");
  }
  line.part("min pointing margin", number(summary, "min_pointing_margin"));
  const auto tau = number(summary, "max_torque_norm");
  const auto tau_max = number(summary, "tau_max");
  if (tau && tau_max && *tau_max > 0.0) line.part("max |tau|/tau_max", *tau / *tau_max);
  line.part("max wheel torque ratio", number(summary, "max_wheel_torque_ratio"));
  constraints_part(line, summary);
  if (word != "converged") line.part(text(summary, "outcome_reason"));
  return line.str();
}

std::string rigid_body_outcome_line(const json& summary) {
  Line line("done");
  line.part("duration", number(summary, "duration"), "s");
  line.part("final attitude error", number(summary, "final_attitude_error_rad"), "rad");
  line.part("final |omega|", number(summary, "final_omega_norm"), "rad/s");
  line.part("max |tau|", number(summary, "max_torque_norm"), "N m");
  line.part("max relative energy drift", number(summary, "max_energy_drift_rel"));
  return line.str();
}

std::string waypoint_outcome_line(const json& summary) {
  const std::string word = text(summary, "outcome", "unknown");
  Line line(word);
  waypoint_parts(line, summary, number(summary, "max_final_position_error"));
  line.part("max |tau|", number(summary, "max_torque_norm"), "N m");
  if (word != "completed") line.part(text(summary, "outcome_reason"));
  return line.str();
}

namespace {

/// governor = "planned" of kind mission: per slew whether it was planned, its plan's duration and
/// bang-bang ratio and its convergence over the plan (docs/mission.md, "Planned slews").
std::string mission_slews_part(const json& summary) {
  const auto it = summary.is_object() ? summary.find("slews") : summary.end();
  if (it == summary.end() || !it->is_array() || it->empty()) return {};
  std::string t = "slews";
  for (const json& s : *it) {
    t += (t == "slews" ? ": " : " / ") + text(s, "mode", "?");
    const auto plan = s.find("plan");
    const auto T_p = plan != s.end() ? number(*plan, "duration") : std::nullopt;
    const auto ratio = plan != s.end() ? number(*plan, "ratio") : std::nullopt;
    if (flag(s, "planned").value_or(false) && T_p && ratio) {
      t += " planned " + fig(*T_p) + " s (" + fig(*ratio) + "x bang-bang)";
      const auto over = number(s, "convergence_time_over_plan");
      t += over ? ", converged at " + fig(*over) + "x" : std::string(", not converged");
    } else {
      t += " tracked (too short to plan)";
    }
  }
  return t;
}

}  // namespace

std::string mission_outcome_line(const json& summary) {
  const std::string word = text(summary, "outcome", "unknown");
  Line line(word);
  line.detail("governor " + text(summary, "governor", "?"));
  waypoint_parts(line, summary, max_over(summary, "waypoints", "final_position_error"));
  line.part("min pointing margin", number(summary, "min_pointing_margin"));
  const auto tau = number(summary, "max_torque_norm");
  const auto tau_max = number(summary, "tau_max");
  if (tau && tau_max && *tau_max > 0.0) line.part("max |tau|/tau_max", *tau / *tau_max);
  constraints_part(line, summary);
  line.part(mission_slews_part(summary));
  const auto time_cost = number(summary, "time_cost");
  const auto dv_cost = number(summary, "delta_v_cost");
  if (time_cost && dv_cost) {
    line.part("the constraints cost " + fig(*time_cost) + " s and " + fig(*dv_cost) +
              " m/s against the unconstrained twin");
  }
  if (word != "completed") line.part(text(summary, "outcome_reason"));
  return line.str();
}

std::string reach_outcome_line(const json& reach) {
  const std::string verdict = text(reach, "verdict", "unknown");
  Line line(verdict);
  if (verdict == "cannot_prove") {
    // The first unproved instant and the analysis step that holds it.
    std::string where;
    if (const auto t = number(reach, "first_failure_time")) where = "first unproved at t = " + fig(*t) + " s";
    const auto steps = reach.is_object() ? reach.find("steps") : reach.end();
    if (steps != reach.end() && steps->is_array()) {
      for (const json& st : *steps) {
        if (flag(st, "safe") != false) continue;
        const auto t0 = number(st, "t");
        const auto t1 = number(st, "t_end");
        // The first cell's steps: named only when the first unproved instant is in that step.
        const auto tf = number(reach, "first_failure_time");
        if (t0 && t1 && (!tf || (*tf >= *t0 && *tf <= *t1))) {
          where += (where.empty() ? "first unproved step [" : ", in step [") + fig(*t0) + ", " +
                   fig(*t1) + "] s";
        }
        break;
      }
    }
    line.detail(where);
  }
  const json* last = nullptr;
  if (reach.is_object()) {
    const auto steps = reach.find("steps");
    if (steps != reach.end() && steps->is_array() && !steps->empty()) last = &steps->back();
  }
  if (last != nullptr) {
    line.part("final ball r", number(*last, "r"));
    line.part("attitude within", number(*last, "attitude_radius"), "rad");
  }
  const json& adversarial = reach.is_object() && reach.contains("adversarial") ? reach["adversarial"] : json();
  line.part("tightness (claimed/seen attitude spread)", number(adversarial, "attitude_tightness"));
  // The steps and cells used (docs/reach.md, "Adaptive steps", "Automatic splitting").
  if (const long steps = count(reach, "n_steps"); steps > 0) {
    const bool adaptive = text(reach, "step_mode", "fixed") == "adaptive";
    line.part(std::to_string(steps) + (adaptive ? " adaptive steps" : " steps"));
  }
  if (const long cells = count(reach, "cells"); cells > 1) {
    const json& part = reach.is_object() && reach.contains("partition") ? reach["partition"] : json();
    const long splits = count(part, "cells_split");
    line.part(std::to_string(cells) + " cells" +
              (splits > 0 ? " (" + std::to_string(splits) + (splits == 1 ? " cell split)" : " cells split)") : ""));
  }
  if (reach.is_object() && reach.contains("soundness")) {
    const json& sound = reach["soundness"];
    if (const long samples = count(sound, "samples"); samples > 0) {
      line.part(std::to_string(count(sound, "inside")) + "/" + std::to_string(samples) +
                " sampled trajectories inside");
    }
  }
  if (verdict == "cannot_prove") line.part(text(reach, "safety_reason"));
  return line.str();
}

std::string campaign_outcome_line(const json& campaign) {
  const long requested = count(campaign, "runs_requested");
  const long completed = count(campaign, "runs_completed");
  const long violations = count(campaign, "violations");
  const char* word = completed < requested ? "partial" : violations > 0 ? "violations" : "done";
  Line line(word);
  line.detail(std::to_string(completed) + " of " + std::to_string(requested) + " runs");
  line.part(std::to_string(count(campaign, "ok")) + " ok, " +
            std::to_string(count(campaign, "rejected")) + " rejected, " +
            std::to_string(count(campaign, "failures")) + " failed");
  if (campaign.is_object() && campaign.contains("outcomes")) {
    const std::string outcomes = campaign::outcome_counts_text(campaign["outcomes"]);
    if (!outcomes.empty()) line.part("outcomes: " + outcomes);
  }
  line.part(std::to_string(violations) + (violations == 1 ? " run" : " runs") +
            " with a constraint violation");
  // The kind's headline figure over the ok runs: best, median and worst.
  const json& figures = campaign.is_object() && campaign.contains("figures") ? campaign["figures"] : json();
  constexpr std::pair<const char*, const char*> kHeadline[] = {
      {"convergence_time", " s"}, {"total_time", " s"}, {"final_attitude_error_rad", " rad"}};
  for (const auto& [key, unit] : kHeadline) {
    if (!figures.is_object() || !figures.contains(key)) continue;
    const json& f = figures[key];
    const auto lo = number(f, "min"), mid = number(f, "p50"), hi = number(f, "max");
    const long n = count(f, "count");
    if (lo && mid && hi) {
      line.part(std::string(key) + " over " + std::to_string(n) + (n == 1 ? " run" : " runs") +
                ": min " + fig(*lo) + ", median " + fig(*mid) + ", max " + fig(*hi) + unit);
    }
    break;
  }
  return line.str();
}

std::string tune_outcome_line(const json& tune) {
  const std::string word = text(tune, "outcome", "unknown");
  Line line(word);
  line.detail(std::to_string(count(tune, "admissible")) + " of " +
              std::to_string(count(tune, "evaluated")) + " points admissible");
  json statuses = json::object(), outcomes = json::object();
  long violating = 0;
  if (tune.is_object() && tune.contains("points") && tune["points"].is_array()) {
    for (const json& p : tune["points"]) {
      const std::string s = text(p, "status", "unknown");
      statuses[s] = statuses.value(s, 0L) + 1;
      if (s == "ok") {
        const std::string o = text(p, "outcome", "unknown");
        outcomes[o] = outcomes.value(o, 0L) + 1;
      }
      if (count(p, "violations") > 0) ++violating;
    }
  }
  line.part(campaign::outcome_counts_text(statuses));
  if (!outcomes.empty()) line.part("outcomes: " + campaign::outcome_counts_text(outcomes));
  line.part(std::to_string(violating) + (violating == 1 ? " point" : " points") + " with a constraint violation");
  const json& best = tune.is_object() && tune.contains("best") ? tune["best"] : json();
  if (best.is_object()) {
    std::string b = "best";
    if (const auto t = number(best, "convergence_time")) b += " " + fig(*t) + " s";
    if (const auto r = number(best, "convergence_time_over_bang_bang")) b += " = " + fig(*r) + "x bang-bang";
    if (best.contains("values") && best["values"].is_object()) {
      std::string values;
      for (const auto& [key, v] : best["values"].items()) {
        if (!v.is_number()) continue;
        values += (values.empty() ? "" : ", ") + key + " = " + fig(v.get<double>());
      }
      if (!values.empty()) b += " at " + values;
    }
    line.part(b);
    if (tune.contains("best_on_bound") && tune["best_on_bound"].is_array() && !tune["best_on_bound"].empty()) {
      std::string keys;
      for (const json& k : tune["best_on_bound"]) {
        if (k.is_string()) keys += (keys.empty() ? "" : ", ") + k.get<std::string>();
      }
      line.part("best on a bound of its range: " + keys + " (widen it with --range)");
    }
  }
  const json& own = tune.is_object() && tune.contains("nominal") ? tune["nominal"] : json();
  if (const auto t = number(own, "convergence_time")) {
    std::string o = "scenario's own values " + fig(*t) + " s";
    if (const auto r = number(own, "convergence_time_over_bang_bang")) o += " = " + fig(*r) + "x";
    line.part(o);
  }
  if (word != "found") line.part(text(tune, "outcome_reason"));
  return line.str();
}

}  // namespace attiguard::app

namespace attiguard::app {

std::string plan_outcome_line(const json& plan) {
  Line line(text(plan, "outcome", "unknown"));
  if (const auto d = number(plan, "duration")) {
    std::string s = fig(*d) + " s";
    if (const auto r = number(plan, "ratio_to_bang_bang")) s += " = " + fig(*r) + "x bang-bang";
    line.detail(s);
  }
  if (const auto m = number(plan, "smallest_cone_margin_deg")) {
    line.part("min cone margin " + fig(*m) + " deg");
  }
  if (const auto t = number(plan, "largest_torque_ratio")) line.part("max |tau|/tau_max " + fig(*t));
  if (plan.is_object() && plan.contains("solver") && plan["solver"].is_object()) {
    const json& s = plan["solver"];
    std::string part = "IPOPT " + text(s, "status", "?");
    if (const auto it = number(s, "iterations")) part += ", " + std::to_string(static_cast<long>(*it)) + " iterations";
    line.part(part);
  }
  if (const auto t = number(plan, "planning_time")) line.part("planned in " + fig(*t) + " s");
  if (plan.is_object() && plan.contains("reason") && plan["reason"].is_string()) {
    line.part(plan["reason"].get<std::string>());
  }
  return line.str();
}

}  // namespace attiguard::app
