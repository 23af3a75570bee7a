#include "attiguard/io/json_file.hpp"

#include <cstring>
#include <fstream>

#include "attiguard/core/errors.hpp"
#include "attiguard/io/partial_file.hpp"

namespace attiguard::io {

void write_json(const std::filesystem::path& path, const nlohmann::json& value) {
  {
    std::ofstream out(partial_path(path), std::ios::binary | std::ios::trunc);
    if (!out) {
      throw InputError("cannot write " + path.string() + ": " + std::strerror(errno));
    }
    out << value.dump(2) << '\n';
    out.flush();
    if (!out) {
      throw InputError("cannot write " + path.string() + ": write failed");
    }
  }
  commit_partial(path);
}

void ensure_directory(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir)) {
    throw InputError("cannot create output directory " + dir.string() + ": " +
                     (ec ? ec.message() : std::string("not a directory")));
  }
}

}  // namespace attiguard::io
