#include "attiguard/app/view_page.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <new>
#include <optional>
#include <sstream>
#include <system_error>
#include <utility>
#include <vector>

#include "attiguard/app/result_summary.hpp"
#include "attiguard/campaign/csv_format.hpp"
#include "attiguard/campaign/envelopes.hpp"
#include "attiguard/campaign/retained_file.hpp"
#include "attiguard/campaign/runs_file.hpp"
#include "attiguard/core/errors.hpp"
#include "attiguard/io/csv_reader.hpp"
#include "attiguard/io/json_reader.hpp"
#include "attiguard/io/json_values.hpp"
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

/// A number for the page: rounded to 9 significant digits, null when not finite.
json rounded(double v) {
  if (!std::isfinite(v)) return nullptr;
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return std::strtod(buf, nullptr);
}

/// A runs.csv cell for the page: a number rounded to 9 significant digits, null for an empty
/// field, the text otherwise (status, reason, outcome: campaign::read_runs_table checked the rest).
json cell(std::string_view text) {
  if (text.empty()) return nullptr;
  double v = 0.0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
  if (r.ec != std::errc{} || r.ptr != text.data() + text.size()) return std::string(text);
  return rounded(v);
}

/// Which rows of a series are shown.
struct Selection {
  std::size_t stride{1};
  /// Keep only rows whose column `filter_column` is below `filter_below` (sampled trajectories
  /// of reach: the first few samples), when set.
  std::string filter_column;
  double filter_below{0.0};
};

/// The page's record of a series: {"file", "columns", "rows_total", "rows_selected",
/// "rows_shown", "stride", "data": {COLUMN: [...]}}.
json series_record(const fs::path& path, const std::vector<std::string>& columns, std::size_t total,
                   std::size_t selected, std::size_t shown, std::size_t stride, json data) {
  json s;
  s["file"] = path.filename().string();
  s["columns"] = columns;
  s["rows_total"] = total;
  s["rows_selected"] = selected;
  s["rows_shown"] = shown;
  s["stride"] = stride;
  s["data"] = std::move(data);
  return s;
}

/// The stride that shows at most `max_rows` (0: all) of `selected` rows.
std::size_t stride_for(std::size_t selected, std::size_t max_rows, std::size_t stride) {
  if (max_rows > 0 && selected > max_rows) return (selected + max_rows - 1) / max_rows;
  return stride;
}

/// The series of a numeric CSV file (column-major), read with the strict reader of export-aem
/// (io::CsvStream) in two passes of constant memory, rows decimated by `sel`; the last selected
/// row is always kept. Absent file: nullopt.
std::optional<json> read_series(const fs::path& path, std::size_t max_rows, Selection sel = {}) {
  std::error_code ec;
  if (!fs::exists(path, ec)) return std::nullopt;
  std::vector<double> row;
  std::size_t total = 0;
  std::size_t selected = 0;
  std::optional<std::size_t> filter;
  const auto passes = [&](const std::vector<double>& r) {
    return !filter || r[*filter] < sel.filter_below;
  };
  {
    io::CsvStream first(path);
    for (std::size_t i = 0; i < first.columns().size(); ++i) {
      if (!sel.filter_column.empty() && first.columns()[i] == sel.filter_column) filter = i;
    }
    while (first.next(row)) {
      ++total;
      if (passes(row)) ++selected;
    }
  }
  const std::size_t stride = stride_for(selected, max_rows, sel.stride);
  io::CsvStream second(path);
  const std::vector<std::string> columns = second.columns();
  std::vector<json> values(columns.size(), json::array());
  std::size_t k = 0;  // position among the selected rows
  std::size_t shown = 0;
  while (second.next(row)) {
    if (!passes(row)) continue;
    if (k % stride == 0 || k + 1 == selected) {
      for (std::size_t c = 0; c < columns.size(); ++c) values[c].push_back(rounded(row[c]));
      ++shown;
    }
    ++k;
  }
  json data = json::object();
  for (std::size_t c = 0; c < columns.size(); ++c) data[columns[c]] = std::move(values[c]);
  return series_record(path, columns, total, selected, shown, stride, std::move(data));
}

/// The series of DIR/runs.csv, read with the strict reader of --resume
/// (campaign::read_runs_table). Absent file: nullopt.
std::optional<json> read_runs_series(const fs::path& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) return std::nullopt;
  const campaign::RunsTable table = campaign::read_runs_table(path);
  std::vector<json> values(table.columns.size(), json::array());
  for (const auto& [index, line] : table.rows) {
    const std::vector<std::string> f = campaign::csv_split(line);
    for (std::size_t c = 0; c < table.columns.size(); ++c) {
      // 64-bit seeds: exact as text, not as a double
      values[c].push_back(table.columns[c] == "seed" ? json(f[c]) : cell(f[c]));
    }
  }
  json data = json::object();
  for (std::size_t c = 0; c < table.columns.size(); ++c) data[table.columns[c]] = std::move(values[c]);
  const std::size_t n = table.rows.size();
  return series_record(path, table.columns, n, n, n, 1, std::move(data));
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
json numbers(const std::vector<double>& v) { return io::json_array(v, rounded); }

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
    page["summary"] = io::read_json_object(dir / "campaign.json");
    if (auto runs = read_runs_series(dir / "runs.csv")) series["runs"] = std::move(*runs);
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
    page["summary"] = io::read_json_object(dir / "reach.json");
    add_series(series, dir, "trajectory.csv", kViewMaxRows);
    add_series(series, dir, "boundary.csv", 0);
    add_series(series, dir, "tube.csv", kViewMaxRows);
    add_series(series, dir, "steps.csv", 0);
    Selection few;
    few.filter_column = "sample";
    few.filter_below = 30;  // 30 sampled trajectories are drawn (docs/viewer.md)
    add_series(series, dir, "samples.csv", 0, few);
  } else if (fs::is_regular_file(dir / "plan.json", ec)) {
    // `attiguard plan`'s folder (docs/slew-planner.md, "Outputs"): the plan drawn as a run.
    page["kind"] = "plan";
    page["summary"] = io::read_json_object(dir / "plan.json");
    if (auto s = read_series(dir / "plan.csv", kViewMaxRows, {})) series["trajectory"] = std::move(*s);
  } else if (fs::is_regular_file(dir / "summary.json", ec)) {
    page["summary"] = read_run_summary(dir / "summary.json");  // the reader of export-aem
    page["kind"] = page["summary"]["kind"];
    add_series(series, dir, "trajectory.csv", kViewMaxRows);
  } else {
    throw InputError(dir.string() + ": no summary.json, reach.json, plan.json or campaign.json (expected "
                                    "the --out DIR of attiguard run, reach, plan or campaign)");
  }
  if (page["kind"] != "campaign" && !series.contains("trajectory")) {
    if (page["kind"] == "plan") {
      throw InputError((dir / "plan.csv").string() + ": not found (the view shows the plan; a plan "
                                                     "that found no admissible path has none)");
    }
    throw InputError((dir / "trajectory.csv").string() + ": not found (the view shows the run's "
                                                         "trajectory; a campaign's runs have one after --replay K)");
  }
  const auto name = page["summary"].find("name");
  page["name"] = name != page["summary"].end() && name->is_string() ? *name : json(dir.filename().string());
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
  json data;
  try {
    data = view_data(dir);
  } catch (const std::bad_alloc&) {  // not the scenario's memory: the results' (failure.cpp)
    throw InputError(dir.string() + ": out of memory reading the results for the view (the files "
                                    "are larger than this machine can hold in memory)");
  }
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
