/// @file output_dir.cpp
/// The output directory of a command (cli/output_dir.hpp).

#include "attiguard/cli/output_dir.hpp"

#include <string>
#include <system_error>

#include "attiguard/core/errors.hpp"

namespace attiguard::cli {

void make_output_dir(const std::filesystem::path& dir) {
  if (dir.empty()) throw InputError("--out: the output directory must not be empty");
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir)) {
    throw InputError(dir.string() + ": cannot create output directory (" +
                     (ec ? ec.message() : std::string("a file of that name exists")) + ")");
  }
}

}  // namespace attiguard::cli
