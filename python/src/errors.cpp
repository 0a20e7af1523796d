// Problems with a run directory (runtime/store's StoreError: missing, foreign, damaged) and
// the module's own (errors.hpp) are raised as esc.Error with their message, the one `esc`
// prints after "esc: error:". The class lives in the pure-Python package (esc/errors.py),
// beside its subclasses; it is looked up when first raised, the package being imported by then.
#include "python/src/bindings.hpp"
#include "python/src/errors.hpp"
#include "runtime/store/results_db.hpp"

namespace esc::python {

namespace py = pybind11;

namespace {

void raise_esc_error(const char* message) {
  const py::object error = py::module_::import("esc.errors").attr("Error");
  PyErr_SetString(error.ptr(), message);
}

}  // namespace

void bind_errors(py::module_& /*m*/) {
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const store::StoreError& e) {
      raise_esc_error(e.what());
    } catch (const Error& e) {
      raise_esc_error(e.what());
    }
  });
}

}  // namespace esc::python
