#include "attiguard/io/output_records.hpp"

#include <fstream>
#include <system_error>

#include <nlohmann/json.hpp>

#include "attiguard/core/errors.hpp"
#include "attiguard/io/partial_file.hpp"

namespace attiguard::io {

namespace {
constexpr const char* kPlotList = "plots.txt";
}  // namespace

void record_plots(const std::filesystem::path& dir, const std::vector<std::filesystem::path>& written) {
  std::ofstream out(dir / kPlotList, std::ios::binary | std::ios::trunc);
  for (const auto& path : written) {
    if (path.extension() == ".png") out << path.filename().string() << '\n';
  }
}

void remove_recorded_plots(const std::filesystem::path& dir) {
  std::ifstream in(dir / kPlotList);
  std::string name;
  while (std::getline(in, name)) {
    const std::filesystem::path file(name);
    if (name.empty() || file.has_parent_path() || file.extension() != ".png") continue;
    std::error_code ec;
    std::filesystem::remove(dir / file, ec);
  }
  in.close();
  std::error_code ec;
  std::filesystem::remove(dir / kPlotList, ec);
}

void write_failure_status(const std::filesystem::path& dir, const std::string& name,
                          const std::string& kind, const std::string& scenario, int exit_code,
                          const std::string& error, const nlohmann::json& result) noexcept {
  try {
    nlohmann::json status = {{"status", "partial"},
                             {"kind", kind.empty() ? nlohmann::json(nullptr) : nlohmann::json(kind)},
                             {"scenario", scenario},
                             {"exit_code", exit_code},
                             {"error", error}};
    if (!result.is_null()) status["result"] = result;
    std::ofstream out(partial_path(dir / name), std::ios::binary | std::ios::trunc);
    out << status.dump(2) << '\n';
  } catch (...) {
  }
}

void write_text(const std::filesystem::path& dir, const std::string& name, const std::string& text) {
  {
    std::ofstream out(partial_path(dir / name), std::ios::binary | std::ios::trunc);
    out << text;
    out.flush();
    if (!out) throw InputError("cannot write " + (dir / name).string() + ": write failed");
  }
  commit_partial(dir / name);
}

}  // namespace attiguard::io
