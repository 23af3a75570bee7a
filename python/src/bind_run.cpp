/// @file bind_run.cpp
/// Scenario runs from Python: the same code paths as `attiguard run`, `check` and `reach`
/// (docs/scenario-format.md, docs/reach.md). Summaries cross the boundary as JSON text.

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "attiguard/reach/reach_run.hpp"
#include "attiguard/scenario/document.hpp"
#include "attiguard/scenario/kinds.hpp"
#include "attiguard/scenario/reach_scenario.hpp"
#include "bindings.hpp"

namespace py = pybind11;

namespace attiguard::python {
namespace {

/// A file path, or TOML text with the label used in error messages.
scenario::Document document_of(const std::string& source, bool is_text, const std::string& label) {
  if (is_text) return scenario::parse_document(source, label);
  return scenario::load_document(source);
}

/// Runs a non-reach scenario kind into out_dir; returns (kind, summary JSON text).
py::tuple run_document(const std::string& source, bool is_text, const std::string& label,
                       const std::string& out_dir) {
  const scenario::Document doc = document_of(source, is_text, label);
  const scenario::KindHandler& handler = scenario::handler_for(doc);
  scenario::RunOptions options;
  options.out_dir = out_dir;
  nlohmann::json summary;
  {
    py::gil_scoped_release release;
    summary = handler.run(doc, options);
  }
  return py::make_tuple(std::string(handler.name), summary.dump());
}

/// Validates a scenario without running it; returns its kind.
std::string check_document(const std::string& source, bool is_text, const std::string& label) {
  const scenario::Document doc = document_of(source, is_text, label);
  const scenario::KindHandler& handler = scenario::handler_for(doc);
  handler.check(doc);
  return std::string(handler.name);
}

/// ConReach on a `reach` scenario (reach paper, Algorithm 1); returns reach.json's text.
/// VerificationFailure propagates after reach.json has been written.
std::string reach_document(const std::string& source, bool is_text, const std::string& label,
                           const std::string& out_dir) {
  const scenario::Document doc = document_of(source, is_text, label);
  const scenario::ReachScenario sc = scenario::parse_reach(doc);
  nlohmann::json summary;
  {
    py::gil_scoped_release release;
    summary = reach::run_reach(sc, out_dir);
  }
  return summary.dump();
}

}  // namespace

void bind_run(py::module_& m) {
  m.def("_run", &run_document, py::arg("source"), py::arg("is_text"), py::arg("label"),
        py::arg("out_dir"));
  m.def("_check", &check_document, py::arg("source"), py::arg("is_text"), py::arg("label"));
  m.def("_reach", &reach_document, py::arg("source"), py::arg("is_text"), py::arg("label"),
        py::arg("out_dir"));
}

}  // namespace attiguard::python
