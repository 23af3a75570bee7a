#pragma once
/// @file table_reader.hpp
/// Typed, validated access to one TOML table of a scenario, with errors that name the file,
/// line, column and full key path, and rejection of keys that were never read.
///
/// Every accessor throws InputError with a one-line message of the form
///   FILE:LINE:COL: KEY.PATH: what is wrong (what was expected)
/// where LINE:COL is the position of the offending value (or of the table for a missing key).

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "attiguard/scenario/document.hpp"

namespace attiguard::scenario {

/// Bounds for a number. NaN and ±inf are always rejected.
struct NumberRule {
  std::optional<double> min;  ///< lower bound
  std::optional<double> max;  ///< upper bound
  bool min_exclusive{false};
  bool max_exclusive{false};
  /// > 0
  static NumberRule positive() { return {0.0, std::nullopt, true, false}; }
  /// ≥ 0
  static NumberRule non_negative() { return {0.0, std::nullopt, false, false}; }
  /// [lo, hi]
  static NumberRule range(double lo, double hi) { return {lo, hi, false, false}; }
};

/// The fallback of an optional number when it is computed from other values of the scenario
/// (e.g. attitude_bias_bound = the norm of attitude_bias), not a constant of the schema: the
/// resolved scenario of a campaign leaves it out (docs/conventions.md, "Outputs";
/// RecordedDefault::derived), as each dispersed run derives it again.
struct DerivedDefault {
  double value;
};

/// Reader over one table; sub-tables share the file and the set of keys seen.
class TableReader {
 public:
  /// Reader over the whole document (top-level table, key path "").
  explicit TableReader(const Document& doc);

  /// True when `key` is present. Asking declares the key as part of this table's schema: it is
  /// listed among the expected keys of "unknown key" messages and finish() accepts it. Declaring
  /// every key of a table before reading any also lets a typo of a required key be reported as
  /// "unknown key 'kpp' … did you mean 'kp'?" rather than as the required key missing.
  [[nodiscard]] bool has(std::string_view key) const;

  /// Declares `key` (see has()) as used only when `used` (what the table's other settings
  /// decide, e.g. disturbance_update only with disturbance = "adversarial"). When it is not used:
  /// a present key is refused with `message` located at it, and an absent key's default is not
  /// written into the resolved scenario (docs/conventions.md, "Outputs"), which would refuse it.
  /// The one definition of "this key is used when …" for both.
  void used_only_if(std::string_view key, bool used, std::string_view message) const;

  /// A required number (integers are accepted as numbers).
  [[nodiscard]] double number(std::string_view key, const NumberRule& rule = {}) const;
  /// An optional number, `fallback` when absent.
  [[nodiscard]] double number_or(std::string_view key, double fallback,
                                 const NumberRule& rule = {}) const;
  /// An optional number whose fallback is derived from other values (DerivedDefault).
  [[nodiscard]] double number_or(std::string_view key, DerivedDefault fallback,
                                 const NumberRule& rule = {}) const;
  /// A required integer with bounds.
  [[nodiscard]] long integer(std::string_view key, long min, long max) const;
  [[nodiscard]] long integer_or(std::string_view key, long fallback, long min, long max) const;
  [[nodiscard]] bool boolean_or(std::string_view key, bool fallback) const;
  /// A required string; when `allowed` is not empty it must be one of them.
  [[nodiscard]] std::string string(std::string_view key,
                                   std::span<const std::string_view> allowed = {}) const;
  [[nodiscard]] std::string string_or(std::string_view key, std::string_view fallback,
                                      std::span<const std::string_view> allowed = {}) const;

  /// An array of exactly 3 finite numbers.
  [[nodiscard]] Eigen::Vector3d vector3(std::string_view key) const;
  /// A non-zero 3-vector, returned normalised.
  [[nodiscard]] Eigen::Vector3d direction(std::string_view key) const;
  /// A non-empty array of finite numbers, each satisfying `rule`.
  [[nodiscard]] Eigen::VectorXd vector(std::string_view key, const NumberRule& rule = {}) const;
  /// A 3×3 matrix given as an array of 3 rows of 3 finite numbers.
  [[nodiscard]] Eigen::Matrix3d matrix3(std::string_view key) const;

  /// A rotation (body → inertial) given as an inline table with exactly one of:
  ///   { matrix = [[…],[…],[…]] }            orthonormal to 1e-9, det = +1
  ///   { quaternion = [η, x, y, z] }         scalar-first, unit to 1e-9
  ///   { axis = [x, y, z], angle = θ }       or angle_deg; axis non-zero (normalised)
  ///   { rotation_vector = [x, y, z] }       θ k in rad
  [[nodiscard]] Eigen::Matrix3d rotation(std::string_view key) const;

  /// An inertia matrix: 3 principal moments [J1, J2, J3] or a 3×3 matrix; must pass
  /// dynamics::inertia_error (symmetric positive definite, triangle inequality).
  [[nodiscard]] Eigen::Matrix3d inertia(std::string_view key) const;

  /// A required sub-table.
  [[nodiscard]] TableReader table(std::string_view key) const;
  /// An optional sub-table.
  [[nodiscard]] std::optional<TableReader> optional_table(std::string_view key) const;
  /// An optional sub-table whose keys all have defaults: the table, or when it is left out a
  /// reader over an empty table at its key path, so that the defaults are read (and recorded
  /// for the resolved scenario: docs/conventions.md, "Outputs") by the same accessors. Its
  /// errors then name the file without a line.
  [[nodiscard]] TableReader table_or_empty(std::string_view key) const;
  /// A required non-empty array of tables ([[key]] or key = [{…}, …]).
  [[nodiscard]] std::vector<TableReader> array_of_tables(std::string_view key) const;

  /// Full dotted key path of `key` in this table (e.g. "control.kp", "cones[1].axis_b").
  [[nodiscard]] std::string key_path(std::string_view key) const;
  /// Throws InputError located at `key` (or at this table when the key is absent).
  [[noreturn]] void fail(std::string_view key, std::string_view message) const;
  /// Throws InputError located at this table.
  [[noreturn]] void fail_here(std::string_view message) const;

  /// Throws InputError naming the first key of this table (and of every sub-table obtained from
  /// it, recursively) that no accessor read: "unknown key (expected one of: …)".
  void finish() const;

 private:
  struct Shared;
  TableReader(std::shared_ptr<Shared> shared, const toml::table* table, std::string path);
  /// number_or of either kind of fallback.
  [[nodiscard]] double number_or(std::string_view key, double fallback, const NumberRule& rule,
                                 bool derived) const;
  /// Declares `key` as read (see has()) and returns its node, or nullptr when absent.
  const toml::node* take(std::string_view key) const;
  /// Throws the error for an absent required key: "missing required key (expected …)" located at
  /// this table, or "unknown key" at an undeclared key of this table that looks like a typo of it.
  [[noreturn]] void missing(std::string_view key, std::string_view expected) const;
  /// A sub-table reader over `table` at key path `path`, registered for finish().
  TableReader child(const toml::table* table, std::string path) const;
  std::shared_ptr<Shared> shared_;
  const toml::table* table_;
  std::string path_;
};

}  // namespace attiguard::scenario
