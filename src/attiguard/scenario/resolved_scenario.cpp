// The resolved scenario: a scenario file with the defaults its readers used filled in.

#include "attiguard/scenario/resolved_scenario.hpp"

#include <algorithm>
#include <sstream>

#include <toml++/toml.h>

#include "attiguard/core/version.hpp"
#include "attiguard/scenario/dispersion.hpp"
#include "attiguard/scenario/document_tree.hpp"
#include "attiguard/scenario/key_path.hpp"

namespace attiguard::scenario {

namespace {
thread_local DefaultsRecorder* t_recorder = nullptr;
/// Inserts the tables on `path` that the file left out (a default of an optional table read
/// through TableReader::table_or_empty, e.g. erg.kappa without [erg]); arrays are not made.
void add_left_out_tables(toml::table& root, std::string_view path) {
  const std::vector<KeyStep> steps = split_key_path(path);
  toml::table* table = &root;
  for (std::size_t s = 0; s + 1 < steps.size() && table != nullptr; ++s) {
    if (steps[s].index) return;
    if (table->get(steps[s].key) == nullptr) table->insert(steps[s].key, toml::table{});
    table = table->get(steps[s].key)->as_table();
  }
}

}  // namespace

DefaultsRecorder::DefaultsRecorder() noexcept {
  if (t_recorder == nullptr) t_recorder = this;
}

DefaultsRecorder::~DefaultsRecorder() {
  if (t_recorder == this) t_recorder = nullptr;
}

void DefaultsRecorder::record(std::string path, DefaultValue value, bool derived) {
  if (t_recorder == nullptr) return;
  const auto& unused = t_recorder->unused_;
  if (std::find(unused.begin(), unused.end(), path) != unused.end()) return;
  t_recorder->defaults_.push_back({std::move(path), std::move(value), derived});
}

void DefaultsRecorder::replace_derived(std::string path, DefaultValue value) {
  if (t_recorder == nullptr) return;
  std::erase_if(t_recorder->defaults_, [&](const RecordedDefault& entry) { return entry.path == path; });
  record(std::move(path), std::move(value), true);
}

void DefaultsRecorder::record_unused(std::string path) {
  if (t_recorder == nullptr) return;
  auto& defaults = t_recorder->defaults_;
  std::erase_if(defaults, [&](const RecordedDefault& entry) { return entry.path == path; });
  t_recorder->unused_.push_back(std::move(path));
}

std::string resolved_toml(const Document& doc, const std::vector<RecordedDefault>& defaults,
                          WrittenDefaults which, std::string_view source) {
  Document resolved = doc;
  toml::table& root = root_table(resolved);
  for (const RecordedDefault& entry : defaults) {
    if (entry.derived && which == WrittenDefaults::constants_only) continue;
    // A quoted key on the path (an entry of [dispersions], "control.kp" = {…}) is not a key
    // path split_key_path reads: such a default (a dispersion's `type`) is not written.
    if (entry.path.find('"') != std::string::npos) continue;
    const std::string& path = entry.path;  // a plain reference: lambdas capture it in C++20
    if (resolve_key_path(root, path) != nullptr) continue;  // present (read twice): keep it
    add_left_out_tables(root, path);
    std::visit([&](const auto& v) { assign_key_path(root, path, v); }, entry.value);
  }
  std::ostringstream out;
  out << "# " << (source.empty() ? doc.path.string() : std::string(source))
      << " resolved by attiguard " << version_string << ": every default its readers used"
      << " is written out"
      << (which == WrittenDefaults::every ? "" : ", but those derived from other values (each dispersed run derives its own)")
      << '\n'
      << toml::toml_formatter(root) << '\n';
  return out.str();
}

std::string resolve_scenario(const Document& doc, void (*check)(const Document&),
                             std::string_view source) {
  const DefaultsRecorder recorder;
  check(doc);
  return resolved_toml(doc, recorder.defaults(), WrittenDefaults::every, source);
}

std::string resolve_campaign(const Document& doc, void (*check)(const Document&)) {
  const DefaultsRecorder recorder;
  check(nominal_document(doc));
  (void)read_dispersions(doc);
  return resolved_toml(doc, recorder.defaults(), WrittenDefaults::constants_only);
}

}  // namespace attiguard::scenario
