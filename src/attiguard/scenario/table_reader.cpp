// TableReader: typed access to the tables of a scenario file, error location, and rejection of
// unknown keys (docs/scenario-format.md, "Common rules" and "Error messages").
// Rotations and inertia matrices are in rotation_value.cpp and inertia_value.cpp.

#include "attiguard/scenario/table_reader.hpp"
#include "attiguard/scenario/resolved_scenario.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <map>
#include <tuple>
#include <utility>

#include "attiguard/core/errors.hpp"
#include "attiguard/scenario/document_tree.hpp"
#include "attiguard/scenario/messages.hpp"

namespace attiguard::scenario {

using detail::describe;
using detail::format_number;

/// State shared by a reader and every reader derived from it: the file name quoted in messages,
/// and for each table the keys declared by the schema code and the sub-tables obtained from it.
struct TableReader::Shared {
  struct TableState {
    std::set<std::string, std::less<>> declared;
    std::vector<std::pair<const toml::table*, std::string>> children;
  };
  std::string file;
  std::map<const toml::table*, TableState> tables;
  /// The empty tables standing for tables left out (table_or_empty); a deque keeps them in place.
  std::deque<toml::table> absent;
};

namespace {

/// "FILE:LINE:COL" (just "FILE" when toml++ recorded no position).
std::string location(const std::string& file, const toml::source_position& pos) {
  if (pos.line == 0) {
    return file;
  }
  return file + ":" + std::to_string(pos.line) + ":" + std::to_string(pos.column);
}

/// Throws the one-line error "FILE:LINE:COL: PATH: message" (no "PATH: " when path is empty).
[[noreturn]] void raise(const std::string& file, const toml::source_position& pos,
                        std::string_view path, std::string_view message) {
  std::string text = location(file, pos) + ": ";
  if (!path.empty()) {
    text.append(path).append(": ");
  }
  text.append(message);
  std::replace(text.begin(), text.end(), '\n', ' ');
  throw InputError(text);
}

/// "> 0", ">= 0", "in [0, 1]", "in (0, 1]": the condition a NumberRule imposes.
std::string describe_rule(const NumberRule& rule) {
  if (rule.min && rule.max) {
    return "in " + std::string(rule.min_exclusive ? "(" : "[") + format_number(*rule.min) + ", " +
           format_number(*rule.max) + (rule.max_exclusive ? ")" : "]");
  }
  if (rule.min) {
    return std::string(rule.min_exclusive ? "> " : ">= ") + format_number(*rule.min);
  }
  if (rule.max) {
    return std::string(rule.max_exclusive ? "< " : "<= ") + format_number(*rule.max);
  }
  return "finite";
}

bool satisfies(double x, const NumberRule& rule) {
  if (rule.min && (rule.min_exclusive ? !(x > *rule.min) : !(x >= *rule.min))) {
    return false;
  }
  if (rule.max && (rule.max_exclusive ? !(x < *rule.max) : !(x <= *rule.max))) {
    return false;
  }
  return true;
}

/// A finite number satisfying `rule` (integers accepted), else an error located at `n`.
double read_number(const std::string& file, const toml::node& n, const std::string& path,
                   const NumberRule& rule) {
  double x = 0.0;
  if (const auto* i = n.as_integer()) {
    x = static_cast<double>(i->get());
  } else if (const auto* f = n.as_floating_point()) {
    x = f->get();
    if (!std::isfinite(x)) {
      raise(file, n.source().begin, path, "must be finite, got " + format_number(x));
    }
  } else {
    raise(file, n.source().begin, path, "expected a number, got " + describe(n));
  }
  if (!satisfies(x, rule)) {
    raise(file, n.source().begin, path,
          "must be " + describe_rule(rule) + ", got " + format_number(x));
  }
  return x;
}

/// "2 elements", "1 element".
std::string count_text(std::size_t n) {
  return std::to_string(n) + (n == 1 ? " element" : " elements");
}

/// An array of finite numbers (each satisfying `rule`) located at `n`; `size` fixes its length.
/// `what` names the expected shape in messages ("an array of 3 numbers").
Eigen::VectorXd read_numbers(const std::string& file, const toml::node& n, const std::string& path,
                             std::optional<std::size_t> size, const NumberRule& rule,
                             const std::string& what) {
  const toml::array* a = n.as_array();
  if (a == nullptr) {
    raise(file, n.source().begin, path, "expected " + what + ", got " + describe(n));
  }
  if (a->empty()) {
    raise(file, n.source().begin, path, "expected " + what + ", got an empty array");
  }
  if (size && a->size() != *size) {
    raise(file, n.source().begin, path, "expected " + what + ", got " + count_text(a->size()));
  }
  Eigen::VectorXd v(static_cast<Eigen::Index>(a->size()));
  for (std::size_t i = 0; i < a->size(); ++i) {
    v(static_cast<Eigen::Index>(i)) =
        read_number(file, *a->get(i), path + "[" + std::to_string(i) + "]", rule);
  }
  return v;
}

}  // namespace

TableReader::TableReader(const Document& doc)
    : shared_(std::make_shared<Shared>()), table_(&root_table(doc)), path_() {
  shared_->file = doc.path.string();
  shared_->tables[table_];
}

TableReader::TableReader(std::shared_ptr<Shared> shared, const toml::table* table, std::string path)
    : shared_(std::move(shared)), table_(table), path_(std::move(path)) {
  shared_->tables[table_];
}

TableReader TableReader::child(const toml::table* table, std::string path) const {
  shared_->tables[table_].children.emplace_back(table, path);
  return TableReader(shared_, table, std::move(path));
}

const toml::node* TableReader::take(std::string_view key) const {
  auto& declared = shared_->tables[table_].declared;
  if (declared.find(key) == declared.end()) {
    declared.emplace(key);
  }
  return table_->get(key);
}

void TableReader::missing(std::string_view key, std::string_view expected) const {
  // A typo of a required key leaves the key missing and an undeclared key in its place: report
  // the typo where it is, which is what the user has to fix.
  const auto& declared = shared_->tables[table_].declared;
  const std::string wanted(key);
  for (auto&& [k, v] : *table_) {
    if (declared.find(k.str()) == declared.end() && detail::is_near_miss(k.str(), wanted)) {
      raise(shared_->file, k.source().begin, key_path(k.str()),
            "unknown key " + detail::quoted(k.str()) + "; did you mean " + detail::quoted(key) +
                "? (required key " + detail::quoted(key) + " is missing)");
    }
  }
  raise(shared_->file, table_->source().begin, key_path(key),
        "missing required key (expected " + std::string(expected) + ")");
}

bool TableReader::has(std::string_view key) const { return take(key) != nullptr; }

void TableReader::used_only_if(std::string_view key, bool used, std::string_view message) const {
  if (used) return;
  if (has(key)) fail(key, message);
  DefaultsRecorder::record_unused(key_path(key));
}

double TableReader::number(std::string_view key, const NumberRule& rule) const {
  const toml::node* n = take(key);
  if (n == nullptr) {
    missing(key, rule.min || rule.max ? "a number " + describe_rule(rule) : "a number");
  }
  return read_number(shared_->file, *n, key_path(key), rule);
}

double TableReader::number_or(std::string_view key, double fallback, const NumberRule& rule) const {
  return number_or(key, fallback, rule, false);
}

double TableReader::number_or(std::string_view key, DerivedDefault fallback,
                              const NumberRule& rule) const {
  return number_or(key, fallback.value, rule, true);
}

double TableReader::number_or(std::string_view key, double fallback, const NumberRule& rule,
                              bool derived) const {
  const toml::node* n = take(key);
  if (n == nullptr) {
    // A fallback outside the rule marks "not set": written out, the reader would refuse it.
    if (std::isfinite(fallback) && satisfies(fallback, rule)) {
      DefaultsRecorder::record(key_path(key), fallback, derived);
    }
    return fallback;
  }
  return read_number(shared_->file, *n, key_path(key), rule);
}

long TableReader::integer(std::string_view key, long min, long max) const {
  const toml::node* n = take(key);
  std::string range = "[";
  range.append(std::to_string(min)).append(", ").append(std::to_string(max)).append("]");
  if (n == nullptr) {
    missing(key, "an integer in " + range);
  }
  const auto* i = n->as_integer();
  if (i == nullptr) {
    fail(key, "expected an integer, got " + describe(*n));
  }
  const std::int64_t x = i->get();
  if (x < min || x > max) {
    fail(key, "must be in " + range + ", got " + std::to_string(x));
  }
  return static_cast<long>(x);
}

long TableReader::integer_or(std::string_view key, long fallback, long min, long max) const {
  if (take(key) == nullptr) {
    if (fallback >= min && fallback <= max) {  // else a "not set" marker, as in number_or
      DefaultsRecorder::record(key_path(key), static_cast<std::int64_t>(fallback));
    }
    return fallback;
  }
  return integer(key, min, max);
}

bool TableReader::boolean_or(std::string_view key, bool fallback) const {
  const toml::node* n = take(key);
  if (n == nullptr) {
    DefaultsRecorder::record(key_path(key), fallback);
    return fallback;
  }
  const auto* b = n->as_boolean();
  if (b == nullptr) {
    fail(key, "expected a boolean (true or false), got " + describe(*n));
  }
  return b->get();
}

std::string TableReader::string(std::string_view key,
                                std::span<const std::string_view> allowed) const {
  const toml::node* n = take(key);
  std::string choices;
  for (const std::string_view a : allowed) {
    choices += (choices.empty() ? "" : ", ") + detail::quoted(a, '"');
  }
  if (n == nullptr) {
    missing(key, allowed.empty() ? "a string" : "one of " + choices);
  }
  const auto* s = n->as_string();
  if (s == nullptr) {
    fail(key, "expected " + (allowed.empty() ? std::string("a string") : "one of " + choices) +
                  ", got " + describe(*n));
  }
  const std::string value = s->get();
  if (allowed.empty() || std::find(allowed.begin(), allowed.end(), value) != allowed.end()) {
    return value;
  }
  const std::vector<std::string> options(allowed.begin(), allowed.end());
  std::string message = "must be one of " + choices + ", got " + detail::quoted(value, '"');
  if (const auto guess = detail::closest_match(value, options)) {
    message += "; did you mean " + detail::quoted(*guess, '"') + "?";
  }
  fail(key, message);
}

std::string TableReader::string_or(std::string_view key, std::string_view fallback,
                                   std::span<const std::string_view> allowed) const {
  if (take(key) == nullptr) {
    if (allowed.empty() || std::find(allowed.begin(), allowed.end(), fallback) != allowed.end()) {
      DefaultsRecorder::record(key_path(key), std::string(fallback));  // else as in number_or
    }
    return std::string(fallback);
  }
  return string(key, allowed);
}

Eigen::Vector3d TableReader::vector3(std::string_view key) const {
  static const std::string what = "an array of 3 numbers";
  const toml::node* n = take(key);
  if (n == nullptr) {
    missing(key, what);
  }
  return read_numbers(shared_->file, *n, key_path(key), 3, {}, what);
}

Eigen::Vector3d TableReader::direction(std::string_view key) const {
  // Scaled by the largest component first, so that [1e300, 1e300, 0] or [1e-300, 0, 0] (whose
  // norm over- or underflows) are the directions they name.
  const Eigen::Vector3d raw = vector3(key);
  const double raw_norm = raw.norm();
  const double scale = raw.cwiseAbs().maxCoeff();
  const bool representable = std::isfinite(raw_norm) && raw_norm >= 1e-150;
  const Eigen::Vector3d v = representable || !(scale > 0.0) ? raw : Eigen::Vector3d(raw / scale);
  const double norm = v.norm();
  if (!(norm > 0.0) || !std::isfinite(norm)) {
    fail(key, "must be a non-zero direction, got [" + format_number(v.x()) + ", " +
                  format_number(v.y()) + ", " + format_number(v.z()) + "]");
  }
  return v / norm;
}

Eigen::VectorXd TableReader::vector(std::string_view key, const NumberRule& rule) const {
  const std::string what = rule.min || rule.max
                               ? "a non-empty array of numbers " + describe_rule(rule)
                               : std::string("a non-empty array of numbers");
  const toml::node* n = take(key);
  if (n == nullptr) {
    missing(key, what);
  }
  return read_numbers(shared_->file, *n, key_path(key), std::nullopt, rule, what);
}

Eigen::Matrix3d TableReader::matrix3(std::string_view key) const {
  static const std::string what = "an array of 3 rows of 3 numbers";
  const toml::node* n = take(key);
  if (n == nullptr) {
    missing(key, what);
  }
  const std::string path = key_path(key);
  const toml::array* rows = n->as_array();
  if (rows == nullptr) {
    raise(shared_->file, n->source().begin, path, "expected " + what + ", got " + describe(*n));
  }
  if (rows->size() != 3) {
    raise(shared_->file, n->source().begin, path,
          "expected " + what + ", got " +
              (rows->empty() ? std::string("an empty array") : count_text(rows->size())));
  }
  Eigen::Matrix3d M;
  for (std::size_t i = 0; i < 3; ++i) {
    const Eigen::VectorXd row =
        read_numbers(shared_->file, *rows->get(i), path + "[" + std::to_string(i) + "]", 3, {},
                     "a row of 3 numbers");
    M.row(static_cast<Eigen::Index>(i)) = row.transpose();
  }
  return M;
}

TableReader TableReader::table(std::string_view key) const {
  const toml::node* n = take(key);
  if (n == nullptr) {
    missing(key, "a table [" + key_path(key) + "]");
  }
  const toml::table* t = n->as_table();
  if (t == nullptr) {
    fail(key, "expected a table, got " + describe(*n));
  }
  return child(t, key_path(key));
}

std::optional<TableReader> TableReader::optional_table(std::string_view key) const {
  if (take(key) == nullptr) {
    return std::nullopt;
  }
  return table(key);
}

TableReader TableReader::table_or_empty(std::string_view key) const {
  if (take(key) != nullptr) return table(key);
  return child(&shared_->absent.emplace_back(), key_path(key));
}

std::vector<TableReader> TableReader::array_of_tables(std::string_view key) const {
  static const std::string what = "a non-empty array of tables";
  const toml::node* n = take(key);
  if (n == nullptr) {
    missing(key, what + " [[" + key_path(key) + "]]");
  }
  const toml::array* a = n->as_array();
  if (a == nullptr) {
    fail(key, "expected " + what + ", got " + describe(*n));
  }
  if (a->empty()) {
    fail(key, "expected " + what + ", got an empty array");
  }
  std::vector<TableReader> out;
  out.reserve(a->size());
  for (std::size_t i = 0; i < a->size(); ++i) {
    const toml::node& e = *a->get(i);
    const std::string path = key_path(key) + "[" + std::to_string(i) + "]";
    const toml::table* t = e.as_table();
    if (t == nullptr) {
      raise(shared_->file, e.source().begin, path, "expected a table, got " + describe(e));
    }
    out.push_back(child(t, path));
  }
  return out;
}

std::string TableReader::key_path(std::string_view key) const {
  const std::string component = detail::path_component(key);
  return path_.empty() ? component : path_ + "." + component;
}

void TableReader::fail(std::string_view key, std::string_view message) const {
  const toml::node* n = table_->get(key);
  raise(shared_->file, n != nullptr ? n->source().begin : table_->source().begin, key_path(key),
        message);
}

void TableReader::fail_here(std::string_view message) const {
  raise(shared_->file, table_->source().begin, path_, message);
}

void TableReader::finish() const {
  // Collect the undeclared keys of this table and of every sub-table obtained from it, and report
  // the one that comes first in the file.
  struct Unknown {
    toml::source_position pos;
    std::string key;
    std::string path;
    const Shared::TableState* state;
  };
  std::optional<Unknown> first;
  std::set<const toml::table*> visited;
  std::vector<std::pair<const toml::table*, std::string>> pending{{table_, path_}};
  while (!pending.empty()) {
    const auto [table, path] = pending.back();
    pending.pop_back();
    if (!visited.insert(table).second) {
      continue;
    }
    const Shared::TableState& state = shared_->tables[table];
    for (auto&& [k, v] : *table) {
      if (state.declared.find(k.str()) != state.declared.end()) {
        continue;
      }
      const toml::source_position pos = k.source().begin;
      if (!first || std::tie(pos.line, pos.column) < std::tie(first->pos.line, first->pos.column)) {
        const std::string component = detail::path_component(k.str());
        first = Unknown{pos, std::string(k.str()),
                        path.empty() ? component : path + "." + component, &state};
      }
    }
    for (const auto& c : state.children) {
      pending.push_back(c);
    }
  }
  if (!first) {
    return;
  }
  const std::vector<std::string> expected(first->state->declared.begin(),
                                          first->state->declared.end());
  std::string message = "unknown key " + detail::quoted(first->key);
  if (expected.empty()) {
    message += " (this table takes no keys)";
  } else {
    std::string list;
    for (const std::string& e : expected) {
      list += (list.empty() ? "" : ", ") + e;
    }
    message += " (expected one of: " + list + ")";
    if (const auto guess = detail::closest_match(first->key, expected)) {
      message += "; did you mean " + detail::quoted(*guess) + "?";
    }
  }
  raise(shared_->file, first->pos, first->path, message);
}

}  // namespace attiguard::scenario
