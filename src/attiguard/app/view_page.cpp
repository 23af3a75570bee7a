#include "attiguard/app/view_page.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>
#include <system_error>
#include <utility>
#include <vector>

#include "attiguard/campaign/csv_format.hpp"
#include "attiguard/campaign/envelopes.hpp"
#include "attiguard/campaign/retained_file.hpp"
#include "attiguard/core/errors.hpp"
#include "attiguard/io/partial_file.hpp"

namespace attiguard::app {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::optional<std::string> slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

json read_json_file(const fs::path& path) {
  const auto text = slurp(path);
  if (!text) throw InputError("cannot read " + path.string());
  json j = json::parse(*text, nullptr, false);
  if (j.is_discarded()) throw InputError(path.string() + ": not valid JSON");
  return j;
}

/// A CSV cell for the page: a number rounded to 9 significant digits, null for an empty field
/// or a non-finite number, the text otherwise (runs.csv status, reason, outcome).
json cell(std::string_view text) {
  if (text.empty()) return nullptr;
  double v = 0.0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
  if (r.ec != std::errc{} || r.ptr != text.data() + text.size()) return std::string(text);
  if (!std::isfinite(v)) return nullptr;
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return std::strtod(buf, nullptr);
}

/// Which rows of a series are shown.
struct Selection {
  std::size_t stride{1};
  /// Keep only rows whose column `filter_column` is below `filter_below` (sampled trajectories
  /// of reach: the first few samples), when set.
  std::string filter_column;
  double filter_below{0.0};
};

/// The series of a CSV file (column-major), rows decimated by `sel`; the last row is always
/// kept. Absent file: nullopt.
std::optional<json> read_series(const fs::path& path, std::size_t max_rows, Selection sel = {}) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::string line;
  std::vector<std::string> columns;
  std::vector<std::vector<std::string>> rows;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    if (columns.empty()) {
      columns = campaign::csv_split(line);
      continue;
    }
    rows.push_back(campaign::csv_split(line));
  }
  std::optional<std::size_t> filter;
  for (std::size_t i = 0; i < columns.size(); ++i) {
    if (!sel.filter_column.empty() && columns[i] == sel.filter_column) filter = i;
  }
  std::vector<std::size_t> kept_all;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    if (filter && (rows[r].size() <= *filter || std::strtod(rows[r][*filter].c_str(), nullptr) >= sel.filter_below)) {
      continue;
    }
    kept_all.push_back(r);
  }
  std::size_t stride = sel.stride;
  if (max_rows > 0 && kept_all.size() > max_rows) stride = (kept_all.size() + max_rows - 1) / max_rows;
  std::vector<std::size_t> kept;
  for (std::size_t k = 0; k < kept_all.size(); k += stride) kept.push_back(kept_all[k]);
  if (!kept_all.empty() && kept.back() != kept_all.back()) kept.push_back(kept_all.back());

  json data = json::object();
  for (std::size_t c = 0; c < columns.size(); ++c) {
    json values = json::array();
    const bool text = columns[c] == "seed";  // 64-bit seeds: exact as text, not as a double
    for (std::size_t r : kept) {
      if (c >= rows[r].size()) {
        values.push_back(nullptr);
      } else {
        values.push_back(text ? json(rows[r][c]) : cell(rows[r][c]));
      }
    }
    data[columns[c]] = std::move(values);
  }
  json s;
  s["file"] = path.filename().string();
  s["columns"] = columns;
  s["rows_total"] = rows.size();
  s["rows_selected"] = kept_all.size();
  s["rows_shown"] = kept.size();
  s["stride"] = stride;
  s["data"] = std::move(data);
  return s;
}

void add_series(json& series, const fs::path& dir, const char* file, std::size_t max_rows,
                Selection sel = {}) {
  if (auto s = read_series(dir / file, max_rows, std::move(sel))) {
    series[fs::path(file).stem().string()] = std::move(*s);
  }
}

/// Escapes "</" so that text cannot close the <script> element holding it.
std::string script_safe(std::string_view text) {
  std::string out;
  out.reserve(text.size() + 64);
  for (std::size_t i = 0; i < text.size(); ++i) {
    out += text[i];
    if (text[i] == '<' && i + 1 < text.size() && text[i + 1] == '/') out += "\\";
  }
  return out;
}

/// A series of numbers for the page (9 significant digits, null for NaN).
json numbers(const std::vector<double>& v) {
  json out = json::array();
  for (double x : v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", x);
    out.push_back(cell(buf));
  }
  return out;
}

/// The envelopes of retained.h5 (campaign::envelope) and the worst runs' series.
json envelopes_json(const fs::path& path) {
  const campaign::RetainedSeries series = campaign::read_retained(path);
  json out;
  out["t"] = numbers(series.t);
  out["runs"] = series.runs;
  json cols = json::array();
  for (std::size_t c = 0; c < series.columns.size(); ++c) {
    const campaign::Envelope e = campaign::envelope(series, c);
    json j;
    j["column"] = e.column;
    j["min"] = numbers(e.min);
    j["p1"] = numbers(e.p1);
    j["p50"] = numbers(e.p50);
    j["p99"] = numbers(e.p99);
    j["max"] = numbers(e.max);
    j["count"] = numbers(e.count);
    json worst = json::array();
    const std::size_t S = series.t.size();
    for (std::size_t k : e.worst) {
      std::vector<double> run(series.values[c].begin() + static_cast<std::ptrdiff_t>(k * S),
                              series.values[c].begin() + static_cast<std::ptrdiff_t>((k + 1) * S));
      worst.push_back({{"run", k}, {"values", numbers(run)}});
    }
    j["worst"] = worst;
    cols.push_back(j);
  }
  out["columns"] = cols;
  return out;
}

}  // namespace

json view_data(const fs::path& dir) {
  std::error_code ec;
  json page;
  json series = json::object();
  if (fs::is_regular_file(dir / "campaign.json", ec)) {
    page["kind"] = "campaign";
    page["summary"] = read_json_file(dir / "campaign.json");
    add_series(series, dir, "runs.csv", 0);
    json runs = json::array();  // replayed runs with their own view
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
      const std::string n = entry.path().filename().string();
      if (entry.is_directory() && n.rfind("run_", 0) == 0) {
        json r;
        r["dir"] = n;
        r["has_view"] = fs::is_regular_file(entry.path() / "view.html", ec);
        runs.push_back(r);
      }
    }
    page["replayed"] = runs;
    if (fs::is_regular_file(dir / "retained.h5", ec)) page["envelopes"] = envelopes_json(dir / "retained.h5");
  } else if (fs::is_regular_file(dir / "reach.json", ec)) {
    page["kind"] = "reach";
    page["summary"] = read_json_file(dir / "reach.json");
    add_series(series, dir, "trajectory.csv", kViewMaxRows);
    add_series(series, dir, "boundary.csv", 0);
    add_series(series, dir, "tube.csv", kViewMaxRows);
    add_series(series, dir, "steps.csv", 0);
    Selection few;
    few.filter_column = "sample";
    few.filter_below = 30;  // 30 sampled trajectories are drawn (docs/viewer.md)
    add_series(series, dir, "samples.csv", 0, few);
  } else if (fs::is_regular_file(dir / "summary.json", ec)) {
    page["summary"] = read_json_file(dir / "summary.json");
    page["kind"] = page["summary"].value("kind", "unknown");
    add_series(series, dir, "trajectory.csv", kViewMaxRows);
  } else {
    throw InputError(dir.string() + ": no summary.json, reach.json or campaign.json (expected the "
                                    "--out DIR of attiguard run, reach or campaign)");
  }
  if (page["kind"] != "campaign" && !series.contains("trajectory")) {
    throw InputError((dir / "trajectory.csv").string() + ": not found (the view shows the run's "
                                                         "trajectory; a campaign's runs have one after --replay K)");
  }
  page["name"] = page["summary"].value("name", dir.filename().string());
  page["series"] = std::move(series);
  page["source_dir"] = dir.filename().string();
  return page;
}

std::string view_html(const json& data, std::string_view bundle) {
  std::string html;
  html += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  html += "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; script-src "
          "'unsafe-inline'; style-src 'unsafe-inline'; img-src data: blob:\">\n";
  html += "<title>attiguard view</title>\n</head>\n<body>\n";
  html += "<script id=\"attiguard-data\" type=\"application/json\">";
  html += script_safe(data.dump(-1, ' ', false, json::error_handler_t::replace));
  html += "</script>\n<script>\n";
  html += script_safe(bundle);
  html += "\n</script>\n</body>\n</html>\n";
  return html;
}

std::string read_viewer_bundle(const fs::path& bundle_path) {
  auto bundle = slurp(bundle_path);
  if (!bundle || bundle->empty()) {
    throw InputError(bundle_path.string() + ": the viewer bundle cannot be read (unset "
                     "ATTIGUARD_VIEWER_BUNDLE to use the one built into attiguard; docs/viewer.md)");
  }
  return std::move(*bundle);
}

fs::path write_view(const fs::path& dir, std::string_view bundle) {
  const json data = view_data(dir);
  const fs::path out = dir / "view.html";
  {
    std::ofstream f(io::partial_path(out), std::ios::binary | std::ios::trunc);
    if (!f) throw InputError("cannot write " + out.string());
    f << view_html(data, bundle);
    f.flush();
    if (!f) throw InputError("cannot write " + out.string() + ": write failed");
  }
  io::commit_partial(out);
  return out;
}

}  // namespace attiguard::app
