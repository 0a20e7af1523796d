#pragma once
// A compiled script as the module holds it: the compiler's result with the caller's settings
// applied, shared (std::shared_ptr) by every object made from it, an Env or a Policy, which
// point into its experiments. Never changed once compiled and set.
#include <filesystem>
#include <memory>
#include <string>

#include "compiler/compiler.hpp"

namespace esc::python {

struct CompiledScript {
  compiler::CompileResult result;
  std::filesystem::path file;   // as given; for a script given as text, its pseudo file name
};

using ScriptPtr = std::shared_ptr<const CompiledScript>;

// The experiment `name` of the script's main file. Raises ValueError naming the experiments
// it declares (and the closest one).
[[nodiscard]] const eval::ExperimentSpec& find_experiment(const CompiledScript& script, const std::string& name);

// The compared controller `name` of `experiment`. Raises ValueError naming those it compares.
[[nodiscard]] const control::ControllerSpec& find_controller(const eval::ExperimentSpec& experiment,
                                                             const std::string& name);

}  // namespace esc::python
