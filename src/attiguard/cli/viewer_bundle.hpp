#pragma once
/// @file viewer_bundle.hpp
/// The viewer's JavaScript bundle built into the attiguard program (docs/viewer.md, "The
/// bundle"): viewer/dist/attiguard_viewer.js, the esbuild output of viewer/src and the three.js
/// of viewer/package-lock.json, kept in the repository and checked against a rebuild by the
/// CTest Viewer.CommittedBundleIsTheBuildOfTheLockFile. Every build of the program, installed
/// copies included, carries it: `attiguard view` needs neither node nor files beside the program.

#include <string_view>

namespace attiguard::cli {

/// The bundle embedded at build time (never empty).
[[nodiscard]] std::string_view embedded_viewer_bundle() noexcept;

}  // namespace attiguard::cli
