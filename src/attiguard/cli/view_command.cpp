/// @file view_command.cpp
/// `attiguard view DIR` and the `--view` step of `run` / `reach` (docs/viewer.md).

#include "attiguard/cli/view_command.hpp"

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <system_error>

#include "attiguard/app/output_folder.hpp"
#include "attiguard/app/view_page.hpp"
#include "attiguard/cli/viewer_bundle.hpp"
#include "attiguard/core/errors.hpp"

namespace attiguard::cli {

std::filesystem::path write_run_view(const std::filesystem::path& dir) {
  // A developer's own rebuild of viewer/src (docs/viewer.md, "Rebuilding the bundle").
  if (const char* env = std::getenv("ATTIGUARD_VIEWER_BUNDLE"); env != nullptr && *env != '\0') {
    return app::write_view(dir, app::read_viewer_bundle(env));
  }
  return app::write_view(dir, embedded_viewer_bundle());
}

void view_command(const std::filesystem::path& dir) {
  // DIR holds the results the view is made of: only DIR/view.html is this command's, and an
  // earlier one (maybe of other results) goes before anything is read (app/output_folder.hpp).
  app::OutputFolder folder(dir, app::OutputCommand::view);
  folder.claim();
  std::error_code ec;
  std::filesystem::path path;
  try {
    if (!std::filesystem::is_directory(dir, ec)) {
      throw InputError(dir.string() + ": not a directory (expected the --out DIR of attiguard run, "
                                      "reach, plan or campaign)");
    }
    path = write_run_view(dir);
    folder.finish();
  } catch (...) {
    folder.fail(std::current_exception());
  }
  const auto bytes = std::filesystem::file_size(path, ec);
  char size[64];
  std::snprintf(size, sizeof size, "%.2f MB", ec ? 0.0 : static_cast<double>(bytes) / 1e6);
  std::cout << "Wrote:\n  " << path.string() << " (" << size << ", opens offline from file://)\n";
}

}  // namespace attiguard::cli
