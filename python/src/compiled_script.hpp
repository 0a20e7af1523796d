#pragma once
// A compiled script as the module holds it: the compiler's result with the caller's settings
// applied, shared (std::shared_ptr) by every object made from it, an Env or a Policy, which
// point into its experiments. Never changed once compiled and set.
#include <filesystem>
#include <map>
#include <memory>
#include <string>

#include "compiler/compiler.hpp"

namespace esc::python {

struct CompiledScript {
  compiler::CompileResult result;
  std::filesystem::path file;   // as given; for a script given as text, its pseudo file name
  // The experiments and studies (by name) that refused the caller's settings, each with the
  // refusal as `esc run --set` words it: `esc run --experiment E --set ...` fails for E, so
  // the file's other experiments stay usable. find_experiment raises it.
  std::map<std::string, std::string, std::less<>> refused;
};

using ScriptPtr = std::shared_ptr<const CompiledScript>;

// The experiment `name` of the script's main file. Raises ValueError naming the experiments
// it declares (and the closest one), and esc.Error where it refused the settings given.
[[nodiscard]] const eval::ExperimentSpec& find_experiment(const CompiledScript& script, const std::string& name);

// The compared controller `name` of `experiment`. Raises ValueError naming those it compares.
[[nodiscard]] const control::ControllerSpec& find_controller(const eval::ExperimentSpec& experiment,
                                                             const std::string& name);

}  // namespace esc::python
