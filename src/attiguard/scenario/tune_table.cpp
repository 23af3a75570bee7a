// The `[tune]` table of a pet_erg scenario (tune_table.hpp; docs/scenario-format.md, "[tune]").

#include "attiguard/scenario/tune_table.hpp"

#include <limits>
#include <string_view>

#include "attiguard/core/errors.hpp"
#include "attiguard/scenario/document_edit.hpp"
#include "attiguard/scenario/document_tree.hpp"
#include "attiguard/scenario/messages.hpp"
#include "attiguard/scenario/table_reader.hpp"

namespace attiguard::scenario {

namespace {

/// One `KEY = [MIN, MAX]` entry of `ranges`; the key must be a number `doc` can hold.
TuneRange read_range(const TableReader& ranges, const std::string& key, const Document& doc) {
  const Eigen::VectorXd v = ranges.vector(key, NumberRule::positive());
  if (v.size() != 2) {
    ranges.fail(key, "expected [MIN, MAX] (2 numbers, 0 < MIN <= MAX), got " +
                         std::to_string(v.size()) + " numbers");
  }
  if (!(v(0) <= v(1))) {
    ranges.fail(key, "MIN " + detail::format_number(v(0)) + " is above MAX " +
                         detail::format_number(v(1)) + " (expected 0 < MIN <= MAX)");
  }
  Document probe = doc;
  try {
    set_number(probe, key, v(0));
  } catch (const InputError& e) {
    const bool not_number = std::string_view(e.what()).ends_with("not a number");
    ranges.fail(key, not_number ? "cannot be tuned: the scenario's value at this key path is not a number"
                                : "cannot be tuned: the scenario has no table to hold this key");
  }
  return {key, v(0), v(1)};
}

}  // namespace

TuneTable read_tune_table(const Document& doc) {
  TuneTable out;
  const TableReader root(doc);
  const std::optional<TableReader> t = root.optional_table("tune");
  if (!t) return out;
  if (t->has("budget")) out.budget = t->integer("budget", 4, std::numeric_limits<long>::max());
  if (t->has("seed")) {
    out.seed = static_cast<std::uint64_t>(t->integer("seed", 0, std::numeric_limits<long>::max()));
  }
  if (t->has("batch")) out.batch = t->integer("batch", 1, std::numeric_limits<long>::max());
  if (t->has("plot")) out.plot = t->boolean_or("plot", true);
  if (t->has("ranges")) {
    const TableReader ranges = t->table("ranges");
    const toml::table* raw = root_table(doc)["tune"]["ranges"].as_table();
    if (raw == nullptr || raw->empty()) {
      ranges.fail_here("[tune] ranges must list at least one KEY = [MIN, MAX]");
    }
    for (const auto& [k, v] : *raw) {
      (void)v;
      out.ranges.push_back(read_range(ranges, std::string(k.str()), doc));
    }
  }
  t->finish();
  return out;
}

}  // namespace attiguard::scenario
