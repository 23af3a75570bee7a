#pragma once
/// @file view_command.hpp
/// `attiguard view DIR`: the self-contained browser view DIR/view.html of a run, reach or
/// campaign folder (docs/viewer.md), and the `--view` step of `run` and `reach`.

#include <filesystem>

namespace attiguard::cli {

/// Writes DIR/view.html and returns its path (app::write_view) with the bundle built into the
/// program, or the file $ATTIGUARD_VIEWER_BUNDLE when that is set (docs/viewer.md). Throws
/// InputError.
std::filesystem::path write_run_view(const std::filesystem::path& dir);

/// `attiguard view DIR`: writes DIR/view.html and prints its path and size.
void view_command(const std::filesystem::path& dir);

}  // namespace attiguard::cli
