#include "attiguard/io/json_reader.hpp"

#include <fstream>
#include <sstream>
#include <system_error>

#include "attiguard/core/errors.hpp"
#include "attiguard/io/csv_reader.hpp"

namespace attiguard::io {

nlohmann::json read_json_object(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw InputError(path.string() + ": cannot read (not a regular file)");
  check_file_size(path, kMaxResultJsonBytes, "a result summary is a small JSON file; is this the right file?");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string() + ": cannot read");
  std::stringstream text;
  text << in.rdbuf();
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text.str());
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(path.string() + ": not valid JSON (at byte " + std::to_string(e.byte) + ")");
  } catch (const nlohmann::json::exception& e) {  // out_of_range.406: a number beyond double
    std::string what = e.what();
    if (const std::size_t end = what.find("] "); what.rfind("[json.exception.", 0) == 0 && end != std::string::npos) {
      what.erase(0, end + 2);
    }
    throw InputError(path.string() + ": not valid JSON (" + what.substr(0, 120) + ")");
  }
  if (!j.is_object()) {
    throw InputError(path.string() + ": expected a JSON object (as attiguard writes), got " +
                     (j.is_array() ? std::string("an array") : std::string("a ") + j.type_name()));
  }
  return j;
}

}  // namespace attiguard::io
