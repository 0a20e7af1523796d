// The ranges the esc program checks its whole-number options against (app/option_ranges.hpp,
// runtime/core/seed_text.hpp), given to the Python package, which checks its arguments
// against the same numbers (esc/_arguments.py) rather than copies of them.
#include <cstdint>
#include <limits>
#include <utility>

#include <pybind11/stl.h>

#include "app/option_ranges.hpp"
#include "python/src/bindings.hpp"
#include "runtime/eval/experiment.hpp"

namespace esc::python {

namespace py = pybind11;

namespace {

py::tuple range_of(const app::OptionRange& r) { return py::make_tuple(r.lowest, r.highest); }

}  // namespace

void bind_limits(py::module_& m) {
  py::dict limits;
  limits["threads"] = range_of(app::kThreadsRange);
  limits["runs"] = range_of(app::kCountRange);
  limits["generations"] = range_of(app::kCountRange);
  limits["seed"] = py::make_tuple(0, std::numeric_limits<std::uint64_t>::max());
  // A script's counts are ints, read from 1 to the largest (compiler/experiment_settings.cpp).
  limits["epochs"] = py::make_tuple(1, std::numeric_limits<decltype(eval::ExperimentSpec::epochs)>::max());
  m.attr("limits") = limits;
}

}  // namespace esc::python
