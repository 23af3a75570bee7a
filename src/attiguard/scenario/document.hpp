#pragma once
/// @file document.hpp
/// A parsed scenario file: its path (for error messages) and its tables. The tables are opaque
/// here (scenario/document_tree.hpp, seen only by scenario/): a layer above reads a document
/// only through scenario/'s functions, so the file format's parser is compiled into scenario/
/// alone (docs/architecture.md, "Layers").

#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

#include <nlohmann/json_fwd.hpp>

namespace attiguard::scenario {

/// The parsed tables of a document (defined in scenario/document_tree.hpp).
struct DocumentTree;

/// A parsed scenario file (docs/scenario-format.md). Copies are deep (a copy may be changed
/// without changing the original: dispersed campaign runs).
class Document {
 public:
  /// An empty document (no key) with an empty path.
  Document();
  /// An empty document (no key) named `path` in messages.
  explicit Document(std::filesystem::path path);
  Document(const Document& other);
  Document& operator=(const Document& other);
  Document(Document&& other) noexcept;
  Document& operator=(Document&& other) noexcept;
  ~Document();

  std::filesystem::path path;  ///< as given by the user; quoted in every error message

  /// The tables (scenario/ only).
  [[nodiscard]] DocumentTree& tree() noexcept { return *tree_; }
  [[nodiscard]] const DocumentTree& tree() const noexcept { return *tree_; }
  /// True when the top-level table has `key` (e.g. "dispersions": a campaign scenario).
  [[nodiscard]] bool has_top_level(std::string_view key) const;

 private:
  std::unique_ptr<DocumentTree> tree_;
};

/// The largest scenario file load_document reads (docs/errors.md): 16 MiB.
inline constexpr std::size_t kMaxScenarioBytes = std::size_t{16} << 20;

/// Reads and parses a scenario file.
/// Throws InputError "FILE:LINE:COL: TOML syntax error: …" on a parse error and
/// "FILE: cannot read scenario file (…)" when the file cannot be opened.
[[nodiscard]] Document load_document(const std::filesystem::path& path);

/// Parses the text of a scenario file held in memory (tests); `path` is used in messages only.
[[nodiscard]] Document parse_document(std::string_view text, const std::filesystem::path& path);

/// A scenario given as a JSON-like value (the Python bindings' dicts, docs/python.md) with the
/// structure of a scenario file: objects are tables, arrays of objects arrays of tables, other
/// arrays arrays, and numbers, booleans and strings values. `path` is used in messages only
/// ("<dict>"); the values are then validated by the same readers as a file's. Throws InputError
/// naming the key path of a null value.
[[nodiscard]] Document document_from_json(const nlohmann::json& value,
                                          const std::filesystem::path& path);

/// The scenario kind: the required top-level string `kind` (e.g. "rigid_body").
[[nodiscard]] std::string scenario_kind(const Document& doc);

/// Throws InputError "FILE:LINE:COL: KEY: message" located at the top-level `key` (or at the
/// document when it is absent).
[[noreturn]] void fail_at(const Document& doc, std::string_view key, std::string_view message);

/// Throws InputError "FILE:LINE:COL: TABLE.KEY: message" located at `key` of the top-level table
/// `table` (at the table when the key is absent, at the document when the table is).
[[noreturn]] void fail_in_table(const Document& doc, std::string_view table, std::string_view key,
                                std::string_view message);

}  // namespace attiguard::scenario
