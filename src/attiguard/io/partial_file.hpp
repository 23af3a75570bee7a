#pragma once
/// @file partial_file.hpp
/// Output files are written under a temporary name and renamed when complete
/// (docs/conventions.md, "Outputs"): an interrupted or failed run leaves PATH.partial, never a
/// truncated PATH that looks like a result.

#include <filesystem>
#include <initializer_list>

namespace attiguard::io {

/// PATH.partial: where PATH is written until it is complete.
[[nodiscard]] std::filesystem::path partial_path(const std::filesystem::path& path);

/// Renames PATH.partial to PATH (the file is complete); throws InputError on failure.
void commit_partial(const std::filesystem::path& path);

/// Removes DIR/NAME and DIR/NAME.partial for each name: the outputs of an earlier run in DIR,
/// before a new run starts writing its own (so none is left beside the new ones).
void remove_outputs(const std::filesystem::path& dir, std::initializer_list<const char*> names);

}  // namespace attiguard::io
