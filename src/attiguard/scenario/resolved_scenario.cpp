// The resolved scenario: a scenario file with the defaults its readers used filled in.

#include "attiguard/scenario/resolved_scenario.hpp"

#include <algorithm>
#include <sstream>

#include <toml++/toml.h>

#include "attiguard/core/version.hpp"
#include "attiguard/scenario/document_tree.hpp"
#include "attiguard/scenario/key_path.hpp"

namespace attiguard::scenario {

namespace {
thread_local DefaultsRecorder* t_recorder = nullptr;
}  // namespace

DefaultsRecorder::DefaultsRecorder() noexcept {
  if (t_recorder == nullptr) t_recorder = this;
}

DefaultsRecorder::~DefaultsRecorder() {
  if (t_recorder == this) t_recorder = nullptr;
}

void DefaultsRecorder::record(std::string path, DefaultValue value) {
  if (t_recorder == nullptr) return;
  const auto& unused = t_recorder->unused_;
  if (std::find(unused.begin(), unused.end(), path) != unused.end()) return;
  t_recorder->defaults_.emplace_back(std::move(path), std::move(value));
}

void DefaultsRecorder::record_unused(std::string path) {
  if (t_recorder == nullptr) return;
  auto& defaults = t_recorder->defaults_;
  std::erase_if(defaults, [&](const auto& entry) { return entry.first == path; });
  t_recorder->unused_.push_back(std::move(path));
}

std::string resolved_toml(const Document& doc,
                          const std::vector<std::pair<std::string, DefaultValue>>& defaults) {
  Document resolved = doc;
  toml::table& root = root_table(resolved);
  for (const auto& entry : defaults) {
    const std::string& path = entry.first;  // a plain reference: lambdas capture it in C++20
    if (resolve_key_path(root, path) != nullptr) continue;  // present (read twice): keep it
    std::visit([&](const auto& v) { assign_key_path(root, path, v); }, entry.second);
  }
  std::ostringstream out;
  out << "# " << doc.path.string() << " resolved by attiguard " << version_string
      << ": every default its readers used is written out\n"
      << toml::toml_formatter(root) << '\n';
  return out.str();
}

std::string resolve_scenario(const Document& doc, void (*check)(const Document&)) {
  const DefaultsRecorder recorder;
  check(doc);
  return resolved_toml(doc, recorder.defaults());
}

}  // namespace attiguard::scenario
