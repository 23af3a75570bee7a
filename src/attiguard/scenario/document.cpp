// Scenario documents: reading and parsing TOML files (docs/scenario-format.md, "Error messages").

#include "attiguard/scenario/document.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <system_error>

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

}  // namespace

Document parse_document(std::string_view text, const std::filesystem::path& path) {
  Document doc;
  doc.path = path;
#if TOML_EXCEPTIONS
  try {
    doc.root = toml::parse(text, path.string());
  } catch (const toml::parse_error& e) {
    throw InputError(syntax_error_message(path, e));
  }
#else
  toml::parse_result result = toml::parse(text, path.string());
  if (!result) {
    throw InputError(syntax_error_message(path, result.error()));
  }
  doc.root = std::move(result).table();
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
  std::ostringstream content;
  content << in.rdbuf();
  if (in.bad()) {
    throw cannot_read("read error");
  }
  return parse_document(content.str(), path);
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
