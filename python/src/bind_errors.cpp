/// @file bind_errors.cpp
/// attiguard::Error → Python exceptions. The message is the C++ what(), i.e. exactly what the
/// CLI prints after "attiguard: error: " (docs/conventions.md, "Exit codes"). Every library
/// error is one of the family (core/errors.hpp); std::bad_alloc stays Python's MemoryError.

#include <exception>

#include "attiguard/core/errors.hpp"
#include "bindings.hpp"

namespace py = pybind11;

namespace attiguard::python {

void bind_errors(py::module_& m) {
  // Kept alive for the life of the interpreter (pybind11's documented pattern).
  static py::exception<Error> error(m, "Error", PyExc_RuntimeError);
  // InputError is also a ValueError: a bad parameter given to a constructor (SetupError, e.g.
  // Governor(tau_max=-1)) is what Python code expects as a ValueError.
  // Kept for the life of the interpreter (a handle: never released at exit).
  static py::handle input = PyErr_NewException(
      "attiguard._core.InputError", py::make_tuple(error, py::handle(PyExc_ValueError)).ptr(),
      nullptr);
  m.attr("InputError") = input;
  static py::exception<NumericalError> numerical(m, "NumericalError", error.ptr());
  static py::exception<VerificationFailure> verification(m, "VerificationFailure", error.ptr());
  error.attr("exit_code") = static_cast<int>(ExitCode::numerical_failure);
  input.attr("exit_code") = static_cast<int>(ExitCode::invalid_input);
  numerical.attr("exit_code") = static_cast<int>(ExitCode::numerical_failure);
  verification.attr("exit_code") = static_cast<int>(ExitCode::verification_failed);

  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      PyErr_SetString(input.ptr(), e.what());
    } catch (const NumericalError& e) {
      PyErr_SetString(numerical.ptr(), e.what());
    } catch (const VerificationFailure& e) {
      PyErr_SetString(verification.ptr(), e.what());
    } catch (const Error& e) {
      PyErr_SetString(error.ptr(), e.what());
    }
  });
}

}  // namespace attiguard::python
