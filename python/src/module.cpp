// esc._esc: the C++ half of the Python package esc (python/esc/__init__.py is the public API).
#include "python/src/bindings.hpp"

PYBIND11_MODULE(_esc, m) {
  m.doc() = "esc's compiler, simulator and results store, bound for the Python package esc (use `import esc`).";
  m.attr("__version__") = ESC_VERSION_STRING;
  esc::python::bind_errors(m);
  esc::python::bind_limits(m);
  esc::python::bind_script(m);
  esc::python::bind_results(m);
  esc::python::bind_evaluate(m);
  esc::python::bind_env(m);
  esc::python::bind_policy(m);
  esc::python::bind_run(m);
  esc::python::bind_graph(m);
}
