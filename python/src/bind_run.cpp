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
#include <utility>
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
#include "attiguard/scenario/read_reach.hpp"
#include "attiguard/scenario/read_waypoint.hpp"
#include "attiguard/sim/waypoint_prediction.hpp"
#include "bindings.hpp"

namespace py = pybind11;

namespace attiguard::python {
namespace {

/// The label of a dict scenario in messages.
constexpr const char* kDictLabel = "<dict>";

/// The limits of a scenario dict (docs/python.md, "Validation"): a scenario file never needs
/// more than a few levels of tables and arrays (docs/scenario-format.md), so a deeper value is a
/// mistake, refused before it can exhaust the stack; and a value the dict reaches again from
/// inside itself (a cycle) is refused before it can exhaust memory. The count bounds shared
/// sub-values (x = [x0, x0], nested): a tree of that many values is far beyond any scenario.
constexpr std::size_t kMaxDictDepth = 64;
constexpr std::size_t kMaxDictValues = 1000000;

/// Converts a scenario dict into JSON value by value, with the limits above.
class DictReader {
 public:
  /// A Python value of a scenario dict as JSON (bool before int: bool is an int in Python;
  /// numpy arrays and scalars through tolist()). Throws InputError naming the key path otherwise.
  nlohmann::json json_of(const py::handle& v, const std::string& where) {
    if (++values_ > kMaxDictValues) {
      fail(where, "more than " + std::to_string(kMaxDictValues) +
                      " values: beyond the limit of a scenario dict (docs/python.md, \"Validation\")");
    }
    if (py::isinstance<py::bool_>(v)) return v.cast<bool>();
    if (py::isinstance<py::int_>(v)) {
      try {
        return v.cast<long long>();
      } catch (const py::cast_error&) {
        fail(where, "integer " + py::str(v).cast<std::string>().substr(0, 40) +
                        " is beyond the 64-bit range of a scenario integer");
      }
    }
    if (py::isinstance<py::float_>(v)) return v.cast<double>();
    if (py::isinstance<py::str>(v)) return v.cast<std::string>();
    if (v.is_none()) fail(where, "a scenario value cannot be None");
    const bool table = py::isinstance<py::dict>(v) || py::hasattr(v, "items");
    const bool array = !table && !py::hasattr(v, "tolist") &&
                       (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v));
    if (py::hasattr(v, "tolist") && !table) return json_of(v.attr("tolist")(), where);  // numpy
    if (!table && !array) {
      fail(where, "a scenario value cannot be " +
                      py::str(py::type::of(v).attr("__name__")).cast<std::string>());
    }
    // Entering a table or an array: the depth and the cycle check on the open containers.
    if (open_.size() >= kMaxDictDepth) {
      fail(where, "nested deeper than " + std::to_string(kMaxDictDepth) +
                      " tables/arrays: beyond the limit of a scenario dict (docs/python.md, \"Validation\")");
    }
    for (std::size_t i = 0; i < open_.size(); ++i) {
      if (open_[i].first == v.ptr()) {
        fail(where, "refers back to " + (open_[i].second.empty() ? std::string("the scenario dict itself")
                                                                 : "its enclosing value " + open_[i].second) +
                        " (a cycle): a scenario is a tree of tables and arrays");
      }
    }
    open_.emplace_back(v.ptr(), where);
    nlohmann::json out = table ? nlohmann::json::object() : nlohmann::json::array();
    if (table) {
      for (const auto& item : py::reinterpret_borrow<py::object>(v).attr("items")()) {
        const py::tuple kv = item.cast<py::tuple>();
        const std::string key = py::str(kv[0]).cast<std::string>();
        out[key] = json_of(kv[1], where.empty() ? key : where + "." + key);
      }
    } else {
      std::size_t i = 0;
      for (const py::handle item : v) {
        out.push_back(json_of(item, where + "[" + std::to_string(i++) + "]"));
      }
    }
    open_.pop_back();
    return out;
  }

 private:
  [[noreturn]] static void fail(const std::string& where, const std::string& what) {
    throw InputError(std::string(kDictLabel) + ": " + (where.empty() ? std::string("scenario") : where) +
                     ": " + what);
  }

  std::vector<std::pair<const PyObject*, std::string>> open_;
  std::size_t values_{0};
};

/// A scenario path (str) or a dict (the Python layer passes os.fspath() of a path).
scenario::Document document_of(const py::object& source) {
  if (py::isinstance<py::str>(source)) return scenario::load_document(source.cast<std::string>());
  if (!py::isinstance<py::dict>(source) && !py::hasattr(source, "items")) {
    throw py::type_error("scenario must be a scenario file path (str) or a dict, got " +
                         py::str(py::type::of(source).attr("__name__")).cast<std::string>());
  }
  return scenario::document_from_json(DictReader().json_of(source, ""), kDictLabel);
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

/// Validates a scenario without running it, as `attiguard check` (its report too: the planned
/// mode's set-up refusals are found there); returns its kind.
std::string check_document(const py::object& source) {
  const scenario::Document doc = document_of(source);
  const app::KindHandler& handler = app::handler_for(doc);
  handler.check(doc);
  if (handler.check_report != nullptr) (void)handler.check_report(doc);
  return std::string(handler.name);
}

/// The mission-time and Δv prediction of a `waypoint` scenario (docs/waypoint.md, "Prediction"):
/// summary.json's `prediction` as JSON text. Validates like `attiguard check`; another kind is
/// an InputError naming its `kind`.
std::string predict_document(const py::object& source) {
  const scenario::Document doc = document_of(source);
  const app::KindHandler& handler = app::handler_for(doc);
  if (handler.name != "waypoint") {
    scenario::fail_at(doc, "kind", "the mission prediction (attiguard.predict) is for kind \"waypoint\", got \"" +
                                       std::string(handler.name) + "\"");
  }
  return sim::prediction_entry(sim::predict_waypoint_mission(scenario::parse_waypoint(doc))).dump();
}

/// ConReach on a `reach` scenario [ConReach Alg. 1]; returns reach.json's text.
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
  m.def("_predict", &predict_document, py::arg("source"));
  m.def("_reach", &reach_document, py::arg("source"), py::arg("out_dir"));
}

}  // namespace attiguard::python
