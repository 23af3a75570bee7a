#pragma once
/// @file document_tree.hpp
/// The tables of a scenario Document, parsed with toml++ (included by scenario/ only:
/// docs/architecture.md, "Layers").

#include <toml++/toml.h>

#include "attiguard/scenario/document.hpp"

namespace attiguard::scenario {

/// The parsed top-level table of a Document.
struct DocumentTree {
  toml::table root;
};

/// The top-level table of `doc`.
[[nodiscard]] inline toml::table& root_table(Document& doc) noexcept { return doc.tree().root; }
[[nodiscard]] inline const toml::table& root_table(const Document& doc) noexcept {
  return doc.tree().root;
}

}  // namespace attiguard::scenario
