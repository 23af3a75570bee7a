#include "attiguard/scenario/dispersion.hpp"
#include "attiguard/scenario/retain_keys.hpp"

#include <Eigen/Eigenvalues>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <string_view>

#include "attiguard/scenario/document_tree.hpp"
#include "attiguard/scenario/key_path.hpp"
#include "attiguard/core/errors.hpp"
#include "attiguard/dynamics/rigid_body.hpp"
#include "attiguard/lie/quaternion.hpp"
#include "attiguard/lie/so3.hpp"
#include "attiguard/scenario/messages.hpp"
#include "attiguard/scenario/table_reader.hpp"

namespace attiguard::scenario {

namespace {

using lie::Mat3;
using lie::Vec3;

constexpr double kDeg = std::numbers::pi / 180.0;

double as_double(const toml::node& n) { return n.value<double>().value_or(0.0); }

/// The least probability mass a truncated normal must put inside its bounds to be sampled (by
/// rejection: on average at most 1/kMinMass normal draws per value).
constexpr double kMinMass = 1e-3;

/// Φ(b) − Φ(a) of the standard normal, accurate in either tail.
double normal_mass(double a, double b) {
  const double s = std::numbers::sqrt2;
  if (a > 0.0) return 0.5 * (std::erfc(a / s) - std::erfc(b / s));
  if (b < 0.0) return 0.5 * (std::erfc(-b / s) - std::erfc(-a / s));
  return 1.0 - 0.5 * (std::erfc(-a / s) + std::erfc(b / s));
}

/// Refuses a truncated normal around `nominal` whose mass inside its bounds is below kMinMass
/// (σ = 1e6 on [0.1, 1]; mean 0.4, σ = 1e-9 on [10, 11]), with the numbers, at `sigma`.
void require_sampleable_mass(const scenario::TableReader& t, const Dispersion& d, double nominal) {
  const double mean = d.has_mean ? d.mean : nominal;
  const double lo = d.has_bounds ? d.min : nominal - d.delta;
  const double hi = d.has_bounds ? d.max : nominal + d.delta;
  const double mass = normal_mass((lo - mean) / d.sigma, (hi - mean) / d.sigma);
  if (mass >= kMinMass) return;
  std::array<char, 32> buf{};
  std::snprintf(buf.data(), buf.size(), "%.3g", mass);
  const std::string mass_text = buf.data();
  std::string hint;
  if (d.sigma > hi - lo) {
    hint = "sigma is wider than the bounds: for a flat spread use distribution = \"uniform\"";
  } else {
    hint = "the mean lies " + detail::format_number(std::abs(mean < lo ? lo - mean : mean - hi) / d.sigma) +
           " sigma outside the bounds: move the mean inside or widen sigma";
  }
  t.fail("sigma", "a truncated_normal of mean " + detail::format_number(mean) + " and sigma " +
                      detail::format_number(d.sigma) + " has a mass of " + mass_text +
                      " inside [" + detail::format_number(lo) + ", " + detail::format_number(hi) +
                      "] (at least " + detail::format_number(kMinMass) + " is needed to sample it): " +
                      hint);
}

bool is_number_node(const toml::node& n) { return n.is_floating_point() || n.is_integer(); }

/// A value of the scenario that a number dispersion (`number`) or a vector dispersion (a
/// non-empty array of numbers) can disperse; InputError at the entry otherwise.
void require_dispersible(const scenario::TableReader& t, const std::string& key, DispersionType type,
                         const toml::node& value) {
  if (type == DispersionType::number && !is_number_node(value)) {
    t.fail_here("'" + key + "' is not a number in the scenario");
  }
  if (type == DispersionType::vector) {
    const toml::array* a = value.as_array();
    bool ok = a != nullptr && !a->empty();
    if (ok) {
      for (const auto& e : *a) ok = ok && is_number_node(e);
    }
    if (!ok) t.fail_here("'" + key + "' is not an array of numbers in the scenario");
  }
}

/// The bounds of a number or vector dispersion: `min` and `max`, or `delta` around the nominal
/// value (docs/campaigns.md, "Dispersions").
void read_bounds(const scenario::TableReader& t, Dispersion& d, const std::string& dist) {
  const bool has_min = t.has("min");
  const bool has_max = t.has("max");
  const bool has_delta = t.has("delta");
  if (has_min != has_max) t.fail_here("give both 'min' and 'max' or neither");
  d.has_bounds = has_min;
  if (d.has_bounds) {
    d.min = t.number("min");
    d.max = t.number("max");
    if (!(d.min < d.max)) {
      t.fail("max", "must be greater than min (min = " + detail::format_number(d.min) +
                        ", max = " + detail::format_number(d.max) + ")");
    }
  }
  if (has_delta) d.delta = t.number("delta", scenario::NumberRule::positive());
  if (d.has_bounds && has_delta) t.fail("delta", "give either min/max or delta, not both");
  if (d.distribution != Distribution::normal && !d.has_bounds && !has_delta) {
    t.fail_here("a " + dist + " dispersion needs 'min' and 'max' or 'delta'");
  }
  if (d.distribution == Distribution::normal && (d.has_bounds || has_delta)) {
    t.fail_here("a normal dispersion has no bounds (use truncated_normal)");
  }
}

/// A `number` or `vector` entry: its distribution, bounds, sigma and mean, each truncated normal
/// checked to be sampleable around every nominal value.
void read_scalar_entry(const scenario::TableReader& t, Dispersion& d, const std::string& type,
                       const toml::node& value) {
  d.type = type == "number" ? DispersionType::number : DispersionType::vector;
  require_dispersible(t, d.key, d.type, value);
  static constexpr std::array<std::string_view, 3> kDist{"uniform", "normal", "truncated_normal"};
  const std::string dist = t.string("distribution", kDist);
  d.distribution = dist == "uniform"  ? Distribution::uniform
                   : dist == "normal" ? Distribution::normal
                                      : Distribution::truncated_normal;
  read_bounds(t, d, dist);
  if (d.distribution != Distribution::uniform) {
    d.sigma = t.number("sigma", scenario::NumberRule::positive());
    d.has_mean = t.has("mean");
    if (d.has_mean) d.mean = t.number("mean");
  }
  if (d.distribution == Distribution::truncated_normal) {
    if (d.type == DispersionType::number) {
      require_sampleable_mass(t, d, as_double(value));
    } else {
      for (const auto& e : *value.as_array()) require_sampleable_mass(t, d, as_double(e));
    }
  }
}

/// An `attitude` entry: uniform over SO(3) or a ball of `max_angle_deg` about the nominal one.
void read_attitude_entry(const scenario::TableReader& t, Dispersion& d, const toml::node& value) {
  d.type = DispersionType::attitude;
  static constexpr std::array<std::string_view, 2> kModes{"uniform", "ball"};
  d.attitude_mode = t.string("mode", kModes) == "uniform" ? AttitudeMode::uniform
                                                           : AttitudeMode::ball;
  if (d.attitude_mode == AttitudeMode::ball) {
    d.max_angle = kDeg * t.number("max_angle_deg", {0.0, 180.0, true, false});
  }
  if (!value.is_table()) t.fail_here("'" + d.key + "' is not a rotation table in the scenario");
}

/// A `direction` entry: a cone of `half_angle_deg` about the nominal 3-vector.
void read_direction_entry(const scenario::TableReader& t, Dispersion& d, const toml::node& value) {
  d.type = DispersionType::direction;
  const toml::array* a = value.as_array();
  bool is_vector3 = a != nullptr && a->size() == 3;
  if (is_vector3) {
    for (const auto& e : *a) is_vector3 = is_vector3 && is_number_node(e);
  }
  if (!is_vector3) t.fail_here("'" + d.key + "' is not a 3-vector in the scenario");
  d.half_angle = kDeg * t.number("half_angle_deg", {0.0, 180.0, true, false});
}

/// A `waypoints` entry (docs/campaigns.md, "[dispersions]"): the key must be the scenario's
/// array of tables `waypoints` whose tables hold only `position`.
void read_waypoints_entry(const scenario::TableReader& t, Dispersion& d, const toml::node& value) {
  d.type = DispersionType::waypoints;
  const toml::array* a = value.as_array();
  bool tables = d.key == "waypoints" && a != nullptr && a->is_array_of_tables();
  if (tables) {
    for (const auto& w : *a) tables = tables && w.as_table()->size() == 1 && w.as_table()->contains("position");
  }
  if (!tables) {
    t.fail_here("'" + d.key + "' is not the scenario's [[waypoints]] (an array of tables holding only "
                "'position'): type \"waypoints\" draws the whole list");
  }
  d.count_min = t.integer_or("count_min", 1, 1, kMaxDispersedWaypoints);
  d.count_max = t.integer_or("count_max", std::max<long>(d.count_min, static_cast<long>(a->size())), 1,
                             kMaxDispersedWaypoints);
  if (d.count_max < d.count_min) {
    t.fail("count_max", "must be >= count_min (" + std::to_string(d.count_min) + "), got " +
                            std::to_string(d.count_max));
  }
  d.leg_min = t.number("leg_min", scenario::NumberRule{0.0, kMaxDispersedLeg, true, false});
  d.leg_max = t.number("leg_max", scenario::NumberRule{0.0, kMaxDispersedLeg, true, false});
  if (d.leg_max < d.leg_min) {
    t.fail("leg_max", "must be >= leg_min (" + detail::format_number(d.leg_min) + "), got " +
                          detail::format_number(d.leg_max));
  }
  d.turn_max = kDeg * t.number_or("turn_max_deg", 180.0, scenario::NumberRule{0.0, 180.0, true, false});
}

/// Reads one `[dispersions]` entry (docs/campaigns.md, "Dispersions").
Dispersion read_entry(const scenario::TableReader& t, const std::string& key,
                      const scenario::Document& nominal) {
  Dispersion d;
  d.key = key;
  static constexpr std::array<std::string_view, 6> kTypes{"number", "vector", "inertia",
                                                          "attitude", "direction", "waypoints"};
  const std::string type = t.string_or("type", "number", kTypes);
  const auto pos = resolve_key_path(root_table(nominal), key);
  if (!pos) t.fail_here("no value at key path '" + key + "' in the scenario");
  const toml::node& value = *pos;
  if (type == "number" || type == "vector") {
    read_scalar_entry(t, d, type, value);
  } else if (type == "inertia") {
    d.type = DispersionType::inertia;
    d.moments_rel_sigma = t.number_or("moments_rel_sigma", 0.0, scenario::NumberRule::range(0.0, 0.3));
    d.axes_max_angle = kDeg * t.number_or("axes_max_angle_deg", 0.0,
                                          scenario::NumberRule::range(0.0, 180.0));
  } else if (type == "attitude") {
    read_attitude_entry(t, d, value);
  } else if (type == "waypoints") {
    read_waypoints_entry(t, d, value);
  } else {
    read_direction_entry(t, d, value);
  }
  return d;
}

/// A scalar draw around `nominal`.
double draw_scalar(const Dispersion& d, double nominal, campaign::Rng& rng) {
  const double mean = d.has_mean ? d.mean : nominal;
  const double lo = d.has_bounds ? d.min : nominal - d.delta;
  const double hi = d.has_bounds ? d.max : nominal + d.delta;
  switch (d.distribution) {
    case Distribution::uniform:
      return rng.uniform(lo, hi);
    case Distribution::normal:
      return mean + d.sigma * rng.normal();
    case Distribution::truncated_normal:
      // read_entry guarantees a mass >= kMinMass inside [lo, hi]: 10^7 draws all outside have
      // probability below e^-10000. Never the mean in their stead (that was a silent bias).
      for (long i = 0; i < 10000000; ++i) {
        const double x = mean + d.sigma * rng.normal();
        if (x >= lo && x <= hi) return x;
      }
      throw NumericalError("dispersions.\"" + d.key + "\": no truncated_normal draw inside [" +
                           detail::format_number(lo) + ", " + detail::format_number(hi) +
                           "] in 10^7 tries");
  }
  return nominal;
}

/// A unit vector uniform on the sphere.
Vec3 unit_vector(campaign::Rng& rng) {
  const double z = rng.uniform(-1.0, 1.0);
  const double phi = rng.uniform(0.0, 2.0 * std::numbers::pi);
  const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  return {r * std::cos(phi), r * std::sin(phi), z};
}

/// A rotation vector uniform (Haar measure) within the geodesic ball of radius max_angle.
Vec3 ball_rotation(double max_angle, campaign::Rng& rng) {
  const double norm = 1.0 - std::cos(max_angle);
  for (int i = 0; i < 100000; ++i) {
    const double theta = rng.uniform(0.0, max_angle);
    if (rng.uniform01() * norm <= 1.0 - std::cos(theta)) return theta * unit_vector(rng);
  }
  return Vec3::Zero();
}

/// A unit vector uniform on the cap of half-angle `alpha` around the unit vector `n`.
Vec3 cap_vector(const Vec3& n, double alpha, campaign::Rng& rng) {
  const double c = 1.0 - rng.uniform01() * (1.0 - std::cos(alpha));
  const double s = std::sqrt(std::max(0.0, 1.0 - c * c));
  const double phi = rng.uniform(0.0, 2.0 * std::numbers::pi);
  const Vec3 helper = std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 e1 = n.cross(helper).normalized();
  const Vec3 e2 = n.cross(e1);
  return (c * n + s * (std::cos(phi) * e1 + std::sin(phi) * e2)).normalized();
}

toml::array array3(const Vec3& v) { return toml::array{v(0), v(1), v(2)}; }

/// Reads the nominal rotation or inertia with the scenario's own readers.
scenario::TableReader single_value_reader(const scenario::Document& holder) {
  return scenario::TableReader(holder);
}

scenario::Document holder_of(const scenario::Document& nominal, const toml::node& value) {
  scenario::Document h(nominal.path);
  root_table(h).insert("value", value);
  return h;
}

}  // namespace

scenario::Document nominal_document(const scenario::Document& doc) {
  scenario::Document nominal = doc;
  root_table(nominal).erase("dispersions");
  root_table(nominal).erase("campaign");
  return nominal;
}

DispersionPlan read_dispersions(const scenario::Document& doc) {
  const scenario::Document nominal = nominal_document(doc);
  scenario::TableReader root(doc);
  DispersionPlan plan;
  const scenario::TableReader table = root.table("dispersions");
  const toml::table* raw = root_table(doc)["dispersions"].as_table();
  if (raw->empty()) table.fail_here("[dispersions] must list at least one dispersed value");
  for (const auto& [k, v] : *raw) {
    (void)v;
    const std::string key(k.str());
    plan.items.push_back(read_entry(table.table(key), key, nominal));
  }
  if (const auto c = root.optional_table("campaign")) {
    plan.max_attempts = c->integer_or("max_attempts", 1, 1, 1000000);
    plan.retain = read_retain(*c, doc);
  }
  table.finish();
  if (const auto c = root.optional_table("campaign")) c->finish();
  return plan;
}

void check_dispersion_bounds(const DispersionPlan& plan, const scenario::Document& doc,
                             void (*check)(const scenario::Document&)) {
  const scenario::Document nominal = nominal_document(doc);
  const scenario::TableReader dispersions = scenario::TableReader(doc).table("dispersions");
  for (const Dispersion& d : plan.items) {
    if (d.type != DispersionType::number || d.distribution != Distribution::normal) continue;
    const toml::node* nom = resolve_key_path(root_table(nominal), d.key);
    const double mean = d.has_mean ? d.mean : (nom != nullptr ? as_double(*nom) : 0.0);
    for (const double side : {-1.0, 1.0}) {
      const double x = mean + side * kNormalProbeSigmas * d.sigma;
      scenario::Document probe = nominal;
      assign_key_path(root_table(probe), d.key, toml::value<double>(x));
      try {
        check(probe);
      } catch (const InputError& e) {
        const std::string what = e.what();
        const std::string at_key = ": " + d.key + ": ";
        const auto pos = what.find(at_key);
        if (pos == std::string::npos) continue;  // refused elsewhere: a rejected draw
        dispersions.table(d.key).fail(
            "sigma", "a normal of mean " + detail::format_number(mean) + " and sigma " +
                         detail::format_number(d.sigma) + " crosses a bound of " + d.key +
                         ": at mean " + (side < 0 ? "- " : "+ ") +
                         detail::format_number(kNormalProbeSigmas) + " sigma = " +
                         detail::format_number(x) + " the scenario says '" +
                         what.substr(pos + at_key.size()) +
                         "'; use truncated_normal with min and max inside the bound");
      }
    }
  }
}

std::vector<std::string> dispersion_columns(const DispersionPlan& plan) {
  std::vector<std::string> cols;
  for (const Dispersion& d : plan.items) {
    switch (d.type) {
      case DispersionType::number:
        cols.push_back(d.key);
        break;
      case DispersionType::vector:
        cols.push_back(d.key + "[0]");
        cols.push_back(d.key + "[1]");
        cols.push_back(d.key + "[2]");
        break;
      case DispersionType::inertia:
        for (const char* s : {".J11", ".J22", ".J33", ".J12", ".J13", ".J23"}) cols.push_back(d.key + s);
        break;
      case DispersionType::attitude:
        for (const char* s : {".q_w", ".q_x", ".q_y", ".q_z"}) cols.push_back(d.key + s);
        break;
      case DispersionType::direction:
        for (const char* s : {".x", ".y", ".z"}) cols.push_back(d.key + s);
        break;
      case DispersionType::waypoints:
        cols.push_back(d.key + ".count");
        for (long i = 0; i < d.count_max; ++i) {
          for (const char* s : {"].x", "].y", "].z"}) cols.push_back(d.key + "[" + std::to_string(i) + s);
        }
        break;
    }
  }
  return cols;
}

namespace {

/// A `number` draw (draw_scalar) at its key; its value in `values`.
void apply_number(const Dispersion& d, const toml::node& nom, campaign::Rng& rng, toml::table& root,
                  std::vector<double>& values) {
  const double x = draw_scalar(d, as_double(nom), rng);
  values.push_back(x);
  assign_key_path(root, d.key, toml::value<double>(x));
}

/// A `vector` draw, element by element; the first three values in `values` (0 for missing ones).
void apply_vector(const Dispersion& d, const toml::node& nom, campaign::Rng& rng, toml::table& root,
                  std::vector<double>& values) {
  toml::array out;
  const toml::array& a = *nom.as_array();
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double x = draw_scalar(d, as_double(*a.get(i)), rng);
    if (i < 3) values.push_back(x);
    out.push_back(x);
  }
  for (std::size_t i = a.size(); i < 3; ++i) values.push_back(0.0);
  assign_key_path(root, d.key, std::move(out));
}

/// An `inertia` draw: principal moments scaled by 1 + σ_rel g (g a standard normal truncated at
/// 3), principal axes turned within axes_max_angle, redrawn until the matrix is a valid inertia
/// (dynamics::inertia_error); J11 J22 J33 J12 J13 J23 in `values`.
void apply_inertia(const Dispersion& d, const scenario::Document& nominal, const toml::node& nom,
                   campaign::Rng& rng, toml::table& root, std::vector<double>& values) {
  const scenario::Document h = holder_of(nominal, nom);
  const Mat3 J0 = single_value_reader(h).inertia("value");
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(J0);
  Mat3 J = J0;
  for (int attempt = 0; attempt < 10000; ++attempt) {
    Vec3 m = eig.eigenvalues();
    for (int i = 0; i < 3; ++i) {
      double g = rng.normal();
      while (std::abs(g) > 3.0) g = rng.normal();
      m(i) *= 1.0 + d.moments_rel_sigma * g;
    }
    Mat3 Q = eig.eigenvectors();
    if (d.axes_max_angle > 0.0) Q = Q * lie::exp(ball_rotation(d.axes_max_angle, rng));
    J = Q * m.asDiagonal() * Q.transpose();
    J = 0.5 * (J + J.transpose());
    if (!dynamics::inertia_error(J)) break;
  }
  values.insert(values.end(), {J(0, 0), J(1, 1), J(2, 2), J(0, 1), J(0, 2), J(1, 2)});
  toml::array rows;
  for (int r = 0; r < 3; ++r) rows.push_back(array3(J.row(r).transpose()));
  assign_key_path(root, d.key, std::move(rows));
}

/// An `attitude` draw: uniform on SO(3) or within a geodesic ball about the nominal attitude;
/// its unit quaternion in `values` and at the key.
void apply_attitude(const Dispersion& d, const scenario::Document& nominal, const toml::node& nom,
                    campaign::Rng& rng, toml::table& root, std::vector<double>& values) {
  const scenario::Document h = holder_of(nominal, nom);
  const Mat3 R0 = single_value_reader(h).rotation("value");
  Mat3 R;
  if (d.attitude_mode == AttitudeMode::uniform) {
    Eigen::Vector4d q(rng.normal(), rng.normal(), rng.normal(), rng.normal());
    q.normalize();
    R = lie::quat_to_rotation(q);
  } else {
    R = R0 * lie::exp(ball_rotation(d.max_angle, rng));
  }
  lie::Quat q = lie::rotation_to_quat(R);
  q.normalize();
  values.insert(values.end(), {q(0), q(1), q(2), q(3)});
  toml::table t;
  t.insert("quaternion", toml::array{q(0), q(1), q(2), q(3)});
  assign_key_path(root, d.key, std::move(t));
}

/// A `direction` draw: a unit vector in the cone of half_angle about the nominal direction.
void apply_direction(const Dispersion& d, const toml::node& nom, campaign::Rng& rng, toml::table& root,
                     std::vector<double>& values) {
  const toml::array& a = *nom.as_array();
  const Vec3 n0 = Vec3(as_double(*a.get(0)), as_double(*a.get(1)), as_double(*a.get(2)));
  const Vec3 n = cap_vector(n0.normalized(), d.half_angle, rng);
  values.insert(values.end(), {n(0), n(1), n(2)});
  assign_key_path(root, d.key, array3(n));
}

/// A `waypoints` draw: count uniform in [count_min, count_max], legs log-uniform in
/// [leg_min, leg_max] from [initial] position (the origin when absent), the first direction
/// uniform on the sphere and each next within turn_max of the previous; the count, then x y z
/// of every slot up to count_max (0 beyond the count) in `values`.
void apply_waypoints(const Dispersion& d, const scenario::Document& nominal, campaign::Rng& rng,
                     toml::table& root, std::vector<double>& values) {
  Vec3 p = Vec3::Zero();
  if (const toml::node* p0 = resolve_key_path(root_table(nominal), "initial.position")) {
    if (const toml::array* a = p0->as_array(); a != nullptr && a->size() == 3) {
      p = Vec3(as_double(*a->get(0)), as_double(*a->get(1)), as_double(*a->get(2)));
    }
  }
  const long span = d.count_max - d.count_min + 1;
  const long n = d.count_min + std::min(span - 1, static_cast<long>(rng.uniform01() * static_cast<double>(span)));
  values.push_back(static_cast<double>(n));
  toml::array list;
  Vec3 dir = unit_vector(rng);
  for (long i = 0; i < d.count_max; ++i) {
    if (i >= n) {
      values.insert(values.end(), {0.0, 0.0, 0.0});
      continue;
    }
    if (i > 0) dir = cap_vector(dir, d.turn_max, rng);
    p += dir * std::exp(rng.uniform(std::log(d.leg_min), std::log(d.leg_max)));
    values.insert(values.end(), {p(0), p(1), p(2)});
    toml::table w;
    w.insert("position", array3(p));
    list.push_back(std::move(w));
  }
  assign_key_path(root, d.key, std::move(list));
}

}  // namespace

void apply_dispersions(const DispersionPlan& plan, const scenario::Document& nominal, campaign::Rng& rng,
                       Document& out, std::vector<double>& values) {
  toml::table& root = root_table(out);
  for (const Dispersion& d : plan.items) {
    const toml::node* nom = resolve_key_path(root_table(nominal), d.key);
    if (nom == nullptr) throw InputError(nominal.path.string() + ": no value at '" + d.key + "'");
    switch (d.type) {
      case DispersionType::number:
        apply_number(d, *nom, rng, root, values);
        break;
      case DispersionType::vector:
        apply_vector(d, *nom, rng, root, values);
        break;
      case DispersionType::inertia:
        apply_inertia(d, nominal, *nom, rng, root, values);
        break;
      case DispersionType::attitude:
        apply_attitude(d, nominal, *nom, rng, root, values);
        break;
      case DispersionType::direction:
        apply_direction(d, *nom, rng, root, values);
        break;
      case DispersionType::waypoints:
        apply_waypoints(d, nominal, rng, root, values);
        break;
    }
  }
}

}  // namespace attiguard::scenario
