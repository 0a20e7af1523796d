#include "python/src/compiled_script.hpp"

#include <vector>

#include <pybind11/pybind11.h>

#include "compiler/names.hpp"
#include "python/src/errors.hpp"

namespace esc::python {

namespace {

// "WHAT `name`; it VERB `a` and `b`; did you mean `a`?" as a ValueError.
[[noreturn]] void no_such(const std::string& what, const std::string& name, const char* verb,
                          const std::vector<std::string>& names) {
  std::string message = what + " `" + name + "`; it " + verb + " " +
                        (names.empty() ? std::string("none") : compiler::quoted_list(names, " and "));
  if (const auto near = compiler::closest(name, names)) message += "; did you mean `" + *near + "`?";
  throw pybind11::value_error(message);
}

}  // namespace

const eval::ExperimentSpec& find_experiment(const CompiledScript& script, const std::string& name) {
  std::vector<std::string> names;
  for (const eval::ExperimentSpec& e : script.result.experiments) {
    if (e.name != name) {
      names.push_back(e.name);
      continue;
    }
    if (const auto refused = script.refused.find(name); refused != script.refused.end()) throw Error(refused->second);
    return e;
  }
  no_such(script.file.string() + " has no experiment", name, "declares", names);
}

const control::ControllerSpec& find_controller(const eval::ExperimentSpec& experiment, const std::string& name) {
  std::vector<std::string> names;
  for (const control::ControllerSpec& c : experiment.controllers) {
    if (c.name == name) return c;
    names.push_back(c.name);
  }
  no_such("experiment `" + experiment.name + "` compares no controller", name, "compares", names);
}

}  // namespace esc::python
