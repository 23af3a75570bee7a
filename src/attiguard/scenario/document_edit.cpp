// Number access by key path and TOML output of a Document (document_edit.hpp).

#include "attiguard/scenario/document_edit.hpp"

#include <sstream>

#include "attiguard/core/errors.hpp"
#include "attiguard/scenario/document_tree.hpp"
#include "attiguard/scenario/key_path.hpp"

namespace attiguard::scenario {

std::optional<double> number_at(const Document& doc, std::string_view path) {
  const toml::node* n = resolve_key_path(root_table(doc), path);
  if (n == nullptr) return std::nullopt;
  if (const auto* f = n->as_floating_point()) return f->get();
  if (const auto* i = n->as_integer()) return static_cast<double>(i->get());
  return std::nullopt;
}

void set_number(Document& doc, std::string_view path, double value) {
  toml::table& root = root_table(doc);
  if (const toml::node* n = resolve_key_path(root, path)) {
    if (!n->is_number()) {
      throw InputError(doc.path.string() + ": " + std::string(path) + ": not a number");
    }
    assign_key_path(root, path, toml::value<double>(value));
    return;
  }
  const std::size_t dot = path.rfind('.');
  const std::string_view parent = dot == std::string_view::npos ? std::string_view{} : path.substr(0, dot);
  if (!parent.empty() && parent.find_first_of(".[") == std::string_view::npos &&
      !root.contains(parent)) {
    root.insert_or_assign(std::string(parent), toml::table{});  // e.g. [erg] absent: its defaults
  }
  const toml::node* p = parent.empty() ? &root : resolve_key_path(root, parent);
  if (p == nullptr || !p->is_table() || split_key_path(path).empty()) {
    throw InputError(doc.path.string() + ": " + std::string(path) + ": no such table in the scenario");
  }
  if (parent.empty()) {
    root.insert_or_assign(std::string(path), toml::value<double>(value));
  } else {
    assign_key_path(root, path, toml::value<double>(value));
  }
}

std::string scenario_file_name(std::string_view stem) { return std::string(stem) + ".toml"; }

std::string document_text(const Document& doc) {
  std::ostringstream out;
  out << toml::toml_formatter(root_table(doc));
  return out.str() + "\n";
}

}  // namespace attiguard::scenario
