// Scenario documents: reading and parsing TOML files (docs/scenario-format.md, "Error messages").

#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/document_tree.hpp"

#include <algorithm>
#include <cstdint>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <new>
#include <system_error>
#include <utility>

#include <nlohmann/json.hpp>

#include "attiguard/core/errors.hpp"
#include "attiguard/scenario/table_reader.hpp"

namespace attiguard::scenario {

namespace {

/// "FILE:LINE:COL: TOML syntax error: description", on one line.
std::string syntax_error_message(const std::filesystem::path& path, const toml::parse_error& e) {
  std::ostringstream os;
  os << path.string();
  const toml::source_position pos = e.source().begin;
  if (pos.line != 0) {
    os << ':' << pos.line << ':' << pos.column;
  }
  os << ": TOML syntax error: " << e.description();
  std::string text = os.str();
  std::replace(text.begin(), text.end(), '\n', ' ');
  std::replace(text.begin(), text.end(), '\r', ' ');
  return text;
}

/// Where a converted node goes: a key of a table, or the end of an array.
struct Target {
  toml::table* table{nullptr};
  std::string_view key;
  toml::array* array{nullptr};
  template <class Node>
  void put(Node&& node) const {
    if (table != nullptr) {
      table->insert(key, std::forward<Node>(node));
    } else {
      array->push_back(std::forward<Node>(node));
    }
  }
};

/// Converts the JSON value `v` at key path `where` (for messages) into its TOML node at `to`.
void convert(const nlohmann::json& v, const std::filesystem::path& path, const std::string& where,
             const Target& to);

toml::table table_of(const nlohmann::json& object, const std::filesystem::path& path,
                     const std::string& where) {
  toml::table t;
  for (const auto& [key, value] : object.items()) {
    convert(value, path, where.empty() ? key : where + "." + key, Target{&t, key, nullptr});
  }
  return t;
}

void convert(const nlohmann::json& v, const std::filesystem::path& path, const std::string& where,
             const Target& to) {
  using nlohmann::json;
  switch (v.type()) {
    case json::value_t::object:
      to.put(table_of(v, path, where));
      return;
    case json::value_t::array: {
      toml::array a;
      for (std::size_t i = 0; i < v.size(); ++i) {
        convert(v[i], path, where + "[" + std::to_string(i) + "]", Target{nullptr, {}, &a});
      }
      to.put(std::move(a));
      return;
    }
    case json::value_t::boolean:
      to.put(v.get<bool>());
      return;
    case json::value_t::number_integer:
      to.put(v.get<std::int64_t>());
      return;
    case json::value_t::number_unsigned:
      if (v.get<std::uint64_t>() > static_cast<std::uint64_t>(INT64_MAX)) {
        throw InputError(path.string() + ": " + where + ": integer too large");
      }
      to.put(static_cast<std::int64_t>(v.get<std::uint64_t>()));
      return;
    case json::value_t::number_float:
      to.put(v.get<double>());
      return;
    case json::value_t::string:
      to.put(v.get<std::string>());
      return;
    default:
      throw InputError(path.string() + ": " + where + ": a scenario value cannot be " +
                       (v.is_null() ? std::string("None (null)") : std::string(v.type_name())));
  }
}

}  // namespace

Document document_from_json(const nlohmann::json& value, const std::filesystem::path& path) {
  if (!value.is_object()) {
    throw InputError(path.string() + ": a scenario must be a table (dict), got " +
                     std::string(value.type_name()));
  }
  Document doc(path);
  root_table(doc) = table_of(value, path, "");
  return doc;
}

Document::Document() : tree_(std::make_unique<DocumentTree>()) {}
Document::Document(std::filesystem::path p)
    : path(std::move(p)), tree_(std::make_unique<DocumentTree>()) {}
Document::Document(const Document& other)
    : path(other.path), tree_(std::make_unique<DocumentTree>(*other.tree_)) {}
Document& Document::operator=(const Document& other) {
  if (this != &other) {
    path = other.path;
    tree_ = std::make_unique<DocumentTree>(*other.tree_);
  }
  return *this;
}
// A moved-from document keeps a valid empty tree (tree() is never a null dereference).
Document::Document(Document&& other) noexcept
    : path(std::move(other.path)), tree_(std::exchange(other.tree_, nullptr)) {
  other.tree_.reset(new (std::nothrow) DocumentTree());
}
Document& Document::operator=(Document&& other) noexcept {
  if (this != &other) {
    path = std::move(other.path);
    tree_.swap(other.tree_);
  }
  return *this;
}
Document::~Document() = default;

bool Document::has_top_level(std::string_view key) const { return tree_->root.contains(key); }

void fail_at(const Document& doc, std::string_view key, std::string_view message) {
  TableReader(doc).fail(key, message);
}

void fail_in_table(const Document& doc, std::string_view table, std::string_view key,
                   std::string_view message) {
  const TableReader root(doc);
  if (const auto t = root.optional_table(table)) t->fail(key, message);
  root.fail(std::string(table) + "." + std::string(key), message);
}

Document parse_document(std::string_view text, const std::filesystem::path& path) {
  Document doc(path);
#if TOML_EXCEPTIONS
  try {
    root_table(doc) = toml::parse(text, path.string());
  } catch (const toml::parse_error& e) {
    throw InputError(syntax_error_message(path, e));
  }
#else
  toml::parse_result result = toml::parse(text, path.string());
  if (!result) {
    throw InputError(syntax_error_message(path, result.error()));
  }
  root_table(doc) = std::move(result).table();
#endif
  return doc;
}

Document load_document(const std::filesystem::path& path) {
  const auto cannot_read = [&path](const std::string& why) {
    return InputError(path.string() + ": cannot read scenario file (" + why + ")");
  };
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw cannot_read("it is a directory");
  }
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw cannot_read(errno != 0 ? std::strerror(errno) : "cannot open it");
  }
  // A scenario is a small text file: read at most kMaxScenarioBytes + 1 bytes, so that a huge
  // file or a device that never ends (/dev/zero) is refused at once instead of filling memory.
  std::string content(kMaxScenarioBytes + 1, '\0');
  in.read(content.data(), static_cast<std::streamsize>(content.size()));
  if (in.bad()) {
    throw cannot_read("read error");
  }
  content.resize(static_cast<std::size_t>(in.gcount()));
  if (content.size() > kMaxScenarioBytes) {
    throw cannot_read("larger than " + std::to_string(kMaxScenarioBytes >> 20) +
                      " MiB: a scenario is a small text file; is this the right file?");
  }
  return parse_document(content, path);
}

std::string scenario_kind(const Document& doc) {
  const TableReader root(doc);
  if (!root.has("kind")) {
    root.fail("kind",
              "missing required key: every scenario file names its kind, e.g. "
              "kind = \"rigid_body\"");
  }
  return root.string("kind");
}

}  // namespace attiguard::scenario
