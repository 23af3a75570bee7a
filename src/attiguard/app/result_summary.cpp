#include "attiguard/app/result_summary.hpp"

#include <string>

#include "attiguard/app/kinds.hpp"
#include "attiguard/core/errors.hpp"
#include "attiguard/io/json_reader.hpp"

namespace attiguard::app {

nlohmann::json read_run_summary(const std::filesystem::path& path) {
  nlohmann::json j = io::read_json_object(path);
  std::string known;
  bool found = false;
  const auto kind = j.find("kind");
  for (const KindHandler& k : kinds()) {
    if (k.name == "reach") continue;  // reach writes reach.json, not summary.json
    known += (known.empty() ? "" : ", ") + std::string(k.name);
    found = found || (kind != j.end() && kind->is_string() && kind->get<std::string>() == k.name);
  }
  if (!found) {
    const std::string got = kind == j.end() ? std::string("no \"kind\"")
                            : kind->is_string() ? "\"" + kind->get<std::string>().substr(0, 40) + "\""
                                                : std::string("a ") + kind->type_name();
    throw InputError(path.string() + ": kind: expected the kind of a run (" + known + "), got " + got +
                     " (not a summary.json attiguard writes)");
  }
  if (const auto name = j.find("name"); name != j.end() && !name->is_string()) {
    throw InputError(path.string() + ": name: expected a string, got a " + std::string(name->type_name()));
  }
  return j;
}

}  // namespace attiguard::app
