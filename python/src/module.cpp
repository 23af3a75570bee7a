/// @file module.cpp
/// The extension module `attiguard._core`; the public package is python/package/attiguard.

#include "bindings.hpp"

PYBIND11_MODULE(_core, m) {
  m.doc() = "attiguard C++ core (see docs/python.md); import the `attiguard` package instead.";
  attiguard::python::bind_errors(m);
  attiguard::python::bind_lie(m);
  attiguard::python::bind_run(m);
  attiguard::python::bind_governor(m);
  attiguard::python::bind_guidance(m);
  attiguard::python::bind_plan(m);
  attiguard::python::bind_planned(m);
}
