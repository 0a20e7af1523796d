// Problems with a run directory (app::StoreError: missing, foreign, damaged) and
// the module's own (errors.hpp) are raised as esc.Error with their message, the one `esc`
// prints after "esc: error:". The class lives in the pure-Python package (esc/errors.py),
// beside its subclasses; it is looked up when first raised, the package being imported by then.
#include "app/error.hpp"
#include "app/store_errors.hpp"
#include "python/src/bindings.hpp"
#include "python/src/errors.hpp"

namespace esc::python {

namespace py = pybind11;

namespace {

void raise_esc_error(const char* message) {
  const py::object error = py::module_::import("esc.errors").attr("Error");
  PyErr_SetString(error.ptr(), message);
}

const char* kind_name(app::ErrorKind kind) {
  switch (kind) {
    case app::ErrorKind::Script: return "script";
    case app::ErrorKind::Setting: return "setting";
    case app::ErrorKind::Results: return "results";
    case app::ErrorKind::Dependency: return "dependency";
    case app::ErrorKind::Memory: return "memory";
    case app::ErrorKind::Request: return "request";
  }
  return "";
}

// The application layer's refusal as esc.Error with its whole text (problems and hints,
// details, the script's diagnostics) and its `kind` ("setting", "results", ...).
void raise_app_error(const app::Error& e) {
  std::string message = e.what();
  for (const std::string& line : e.details()) message += "\n" + line;
  if (e.script() != nullptr && !e.problems().empty())
    message += "\n" + compiler::render_all(e.script()->diagnostics, e.script()->sources, false);
  const py::object error = py::module_::import("esc.errors").attr("Error")(message);
  error.attr("kind") = kind_name(e.kind());
  PyErr_SetObject(reinterpret_cast<PyObject*>(Py_TYPE(error.ptr())), error.ptr());
}

}  // namespace

void bind_errors(py::module_& /*m*/) {
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const app::Error& e) {
      raise_app_error(e);
    } catch (const app::StoreError& e) {
      raise_esc_error(e.what());
    } catch (const Error& e) {
      raise_esc_error(e.what());
    }
  });
}

}  // namespace esc::python
