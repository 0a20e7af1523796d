#pragma once
// Compiling a script as every command does, and picking what to run from it.
#include <filesystem>
#include <string>
#include <variant>
#include <vector>

#include "app/events.hpp"
#include "compiler/compiler.hpp"
#include "runtime/store/results_db.hpp"

namespace esc::app {

// `file` compiled with `options`; warnings go to `events`. Throws Error (kind Script, the
// result attached) when it does not compile.
[[nodiscard]] compiler::CompileResult compile(const std::filesystem::path& file, const compiler::CompileOptions& options,
                                              Events& events);

// The experiment `name` of a compiled script (the first one if `name` is empty). Throws
// Error naming the closest declared name.
eval::ExperimentSpec& pick_experiment(compiler::CompileResult& compiled, const std::filesystem::path& file,
                                      const std::string& name);

// The experiment `name` a run stored, among every experiment `file` compiles, imported ones
// included (a dependency cache entry's stored main file may only import it).
eval::ExperimentSpec& pick_stored_experiment(compiler::CompileResult& compiled, const std::filesystem::path& file,
                                             const std::string& name);

// The files a compiled script read, as a run stores them.
[[nodiscard]] std::vector<store::SourceFile> sources_of(const compiler::CompileResult& compiled);

// What `esc run --experiment NAME` picks: an experiment or a study.
using Target = std::variant<eval::ExperimentSpec*, eval::StudySpec*>;

// The experiment or study `name` of a compiled script (when `name` is empty, whichever the
// main file declares first).
[[nodiscard]] Target pick_target(compiler::CompileResult& compiled, const std::filesystem::path& file,
                                 const std::string& name);

}  // namespace esc::app
