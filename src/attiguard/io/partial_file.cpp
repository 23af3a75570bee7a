#include "attiguard/io/partial_file.hpp"

#include <system_error>

#include "attiguard/core/errors.hpp"

namespace attiguard::io {

std::filesystem::path partial_path(const std::filesystem::path& path) {
  return path.string() + ".partial";
}

void commit_partial(const std::filesystem::path& path) {
  std::error_code ec;
  std::filesystem::rename(partial_path(path), path, ec);
  if (ec) throw InputError("cannot write " + path.string() + ": " + ec.message());
}

void remove_outputs(const std::filesystem::path& dir, std::initializer_list<const char*> names) {
  for (const char* name : names) {
    std::error_code ec;
    std::filesystem::remove(dir / name, ec);
    std::filesystem::remove(partial_path(dir / name), ec);
  }
}

}  // namespace attiguard::io
