#pragma once
/// @file view_page.hpp
/// The self-contained browser view of a result folder (docs/viewer.md): DIR/view.html holds the
/// folder's figures and time series as JSON and the viewer's JavaScript bundle (three.js
/// included, built from viewer/ by npm), so that it opens from file:// with no network.

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace attiguard::app {

/// Rows of a trajectory shown at most: a longer one is decimated to every k-th row (plus the
/// last), and the page says so ("decimated for display", docs/viewer.md).
inline constexpr std::size_t kViewMaxRows = 2000;

/// The data of the page for DIR: {"kind", "name", "summary", "series": {NAME: {"columns",
/// "rows_total", "rows_shown", "stride", "data": {COLUMN: [...]}}}, "runs": [...]} from
/// summary.json + trajectory.csv (flight kinds), reach.json + its CSV files (reach) or
/// campaign.json + runs.csv (campaign). Numbers are rounded to 9 significant digits. Throws
/// InputError when DIR holds no result.
[[nodiscard]] nlohmann::json view_data(const std::filesystem::path& dir);

/// The HTML page of `data` with the JavaScript `bundle` inlined ("</" escaped in both).
[[nodiscard]] std::string view_html(const nlohmann::json& data, std::string_view bundle);

/// Writes DIR/view.html with the bundle read from `bundle_path`; returns its path. Throws
/// InputError when the bundle is missing (the viewer was not built: docs/viewer.md).
std::filesystem::path write_view(const std::filesystem::path& dir,
                                 const std::filesystem::path& bundle_path);

}  // namespace attiguard::app
