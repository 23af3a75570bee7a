/// @file bind_run.cpp
/// Scenario runs from Python: the same code paths as `attiguard run`, `check` and `reach`
/// (docs/scenario-format.md, docs/reach.md, docs/python.md). A scenario is a file path or a
/// dict; a dict is converted value by value into a scenario document
/// (scenario::document_from_json) and validated by the same readers as a file. run()'s time
/// series go straight from the simulator into numpy arrays through NumpyRowSink: no temporary
/// file, no CSV reading. Summaries cross the boundary as JSON text.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "attiguard/app/kinds.hpp"
#include "attiguard/app/reach_run.hpp"
#include "attiguard/core/errors.hpp"
#include "attiguard/io/row_sink.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/reach_scenario.hpp"
#include "bindings.hpp"

namespace py = pybind11;

namespace attiguard::python {
namespace {

/// The label of a dict scenario in messages.
constexpr const char* kDictLabel = "<dict>";

/// A Python value of a scenario dict as JSON (bool before int: bool is an int in Python; numpy
/// arrays and scalars through tolist()). Throws InputError naming the key path otherwise.
nlohmann::json json_of(const py::handle& v, const std::string& where) {
  if (py::isinstance<py::bool_>(v)) return v.cast<bool>();
  if (py::isinstance<py::int_>(v)) return v.cast<long long>();
  if (py::isinstance<py::float_>(v)) return v.cast<double>();
  if (py::isinstance<py::str>(v)) return v.cast<std::string>();
  if (v.is_none()) {
    throw InputError(std::string(kDictLabel) + ": " + where + ": a scenario value cannot be None");
  }
  if (py::isinstance<py::dict>(v) || py::hasattr(v, "items")) {
    nlohmann::json out = nlohmann::json::object();
    for (const auto& item : py::reinterpret_borrow<py::object>(v).attr("items")()) {
      const py::tuple kv = item.cast<py::tuple>();
      const std::string key = py::str(kv[0]).cast<std::string>();
      out[key] = json_of(kv[1], where.empty() ? key : where + "." + key);
    }
    return out;
  }
  if (py::hasattr(v, "tolist")) return json_of(v.attr("tolist")(), where);  // numpy
  if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v)) {
    nlohmann::json out = nlohmann::json::array();
    std::size_t i = 0;
    for (const py::handle item : v) {
      out.push_back(json_of(item, where + "[" + std::to_string(i++) + "]"));
    }
    return out;
  }
  throw InputError(std::string(kDictLabel) + ": " + where + ": a scenario value cannot be " +
                   py::str(py::type::of(v).attr("__name__")).cast<std::string>());
}

/// A scenario path (str) or a dict (the Python layer passes os.fspath() of a path).
scenario::Document document_of(const py::object& source) {
  if (py::isinstance<py::str>(source)) return scenario::load_document(source.cast<std::string>());
  return scenario::document_from_json(json_of(source, ""), kDictLabel);
}

/// Collects the rows of a run column by column; to_dict() turns them into numpy arrays.
class NumpyRowSink final : public io::RowSink {
 public:
  void begin(const std::vector<std::string>& columns) override {
    names_ = columns;
    columns_.assign(columns.size(), {});
  }
  void row(std::span<const double> values) override {
    for (std::size_t i = 0; i < columns_.size() && i < values.size(); ++i) {
      columns_[i].push_back(values[i]);
    }
  }
  /// {column name: 1-D float64 array} in column order (needs the GIL).
  [[nodiscard]] py::dict to_dict() const {
    py::dict out;
    for (std::size_t i = 0; i < names_.size(); ++i) {
      const std::vector<double>& c = columns_[i];
      out[py::str(names_[i])] = py::array_t<double>(static_cast<py::ssize_t>(c.size()), c.data());
    }
    return out;
  }

 private:
  std::vector<std::string> names_;
  std::vector<std::vector<double>> columns_;
};

/// Runs a non-reach scenario kind; returns (kind, summary JSON text, {column: numpy array}).
/// With `out_dir` the run also writes DIR/trajectory.csv and DIR/summary.json like the CLI.
py::tuple run_document(const py::object& source, const std::optional<std::string>& out_dir) {
  const scenario::Document doc = document_of(source);
  const app::KindHandler& handler = app::handler_for(doc);
  NumpyRowSink rows;
  app::RunOptions options;
  options.write_files = out_dir.has_value();
  if (out_dir) options.out_dir = *out_dir;
  options.rows = &rows;
  nlohmann::json summary;
  {
    py::gil_scoped_release release;
    summary = handler.run(doc, options);
  }
  return py::make_tuple(std::string(handler.name), summary.dump(), rows.to_dict());
}

/// Validates a scenario without running it; returns its kind.
std::string check_document(const py::object& source) {
  const scenario::Document doc = document_of(source);
  const app::KindHandler& handler = app::handler_for(doc);
  handler.check(doc);
  return std::string(handler.name);
}

/// ConReach on a `reach` scenario (reach paper, Algorithm 1); returns reach.json's text.
/// VerificationFailure propagates after reach.json has been written.
std::string reach_document(const py::object& source, const std::string& out_dir) {
  const scenario::Document doc = document_of(source);
  const reach::ReachScenario sc = scenario::parse_reach(doc);
  nlohmann::json summary;
  {
    py::gil_scoped_release release;
    summary = app::run_reach(sc, out_dir);
  }
  return summary.dump();
}

}  // namespace

void bind_run(py::module_& m) {
  m.def("_run", &run_document, py::arg("source"), py::arg("out_dir") = py::none());
  m.def("_check", &check_document, py::arg("source"));
  m.def("_reach", &reach_document, py::arg("source"), py::arg("out_dir"));
}

}  // namespace attiguard::python
