#pragma once
/// @file view_page.hpp
/// The self-contained browser view of a result folder (docs/viewer.md): DIR/view.html holds the
/// folder's figures and time series as JSON and the viewer's JavaScript bundle (three.js
/// included; viewer/dist/attiguard_viewer.js, built from viewer/src by esbuild and kept in the
/// repository), so that it opens from file:// with no network.

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

/// The text of a viewer bundle file (a developer's rebuild, docs/viewer.md "Rebuilding the
/// bundle"). Throws InputError naming the file when it cannot be read or is empty.
[[nodiscard]] std::string read_viewer_bundle(const std::filesystem::path& bundle_path);

/// Writes DIR/view.html (through DIR/view.html.partial) with the JavaScript `bundle`; returns
/// its path. Throws InputError when DIR holds no result or the file cannot be written.
std::filesystem::path write_view(const std::filesystem::path& dir, std::string_view bundle);

}  // namespace attiguard::app
