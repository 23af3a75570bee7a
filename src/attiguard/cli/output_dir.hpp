#pragma once
/// @file output_dir.hpp
/// The output directory of a command (`--out DIR`, docs/conventions.md "Outputs").

#include <filesystem>

namespace attiguard::cli {

/// Creates DIR and its parents if missing. Throws InputError (exit 2) when DIR is empty or
/// cannot be created (a file of that name, no permission), with the reason.
void make_output_dir(const std::filesystem::path& dir);

}  // namespace attiguard::cli
