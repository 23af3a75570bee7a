#pragma once
/// @file key_path.hpp
/// Dotted key paths into a scenario's TOML table, with array indices: "control.kp",
/// "cones[0].direction_i", "thrusters[2].axis_b".

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <toml++/toml.h>

namespace attiguard::scenario {

/// One step of a key path: a key, then optionally an index into the array it names.
struct KeyStep {
  std::string key;
  std::optional<std::size_t> index;
};

/// Splits a key path; an empty result means the path is malformed.
[[nodiscard]] std::vector<KeyStep> split_key_path(std::string_view path);

/// The node at `path`, nullptr when absent or malformed.
[[nodiscard]] const toml::node* resolve_key_path(const toml::table& root, std::string_view path);

/// Replaces the value at `path` (which must exist: resolve_key_path first).
template <class Value>
void assign_key_path(toml::table& root, std::string_view path, Value&& value) {
  const std::vector<KeyStep> steps = split_key_path(path);
  if (steps.empty()) return;
  toml::table* table = &root;
  for (std::size_t s = 0; s < steps.size(); ++s) {
    const KeyStep& step = steps[s];
    const bool last = s + 1 == steps.size();
    if (last && !step.index) {
      table->insert_or_assign(step.key, std::forward<Value>(value));
      return;
    }
    toml::node* n = table->get(step.key);
    if (n == nullptr) return;
    if (step.index) {
      toml::array* a = n->as_array();
      if (a == nullptr || *step.index >= a->size()) return;
      if (last) {
        a->replace(a->cbegin() + static_cast<std::ptrdiff_t>(*step.index),
                   std::forward<Value>(value));
        return;
      }
      n = a->get(*step.index);
    }
    table = n->as_table();
    if (table == nullptr) return;
  }
}

}  // namespace attiguard::scenario
