#pragma once
// Setting up an experiment the way `esc run`, `esc run --resume` and `esc replay` all do:
// picking it (or a study) from a compiled script, applying command-line settings (given now,
// or stored in a run directory when it started), and naming its source files for the store.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

#include "cli/commands.hpp"
#include "compiler/compiler.hpp"
#include "runtime/store/results_db.hpp"

namespace esc::cli {

// The experiment `name` of a compiled script (the first one if `name` is empty), or null
// after printing an error (with the closest name declared).
eval::ExperimentSpec* pick_experiment(compiler::CompileResult& compiled, const std::filesystem::path& file,
                                      const std::string& name);

// The experiment `name` a run stored, among every experiment `file` compiles, imported ones
// included (a dependency cache entry's stored main file may only import it), or null after
// printing an error.
eval::ExperimentSpec* pick_stored_experiment(compiler::CompileResult& compiled, const std::filesystem::path& file,
                                             const std::string& name);

// What `esc run --experiment NAME` picked: an experiment or a study; monostate after an error.
using Target = std::variant<std::monostate, eval::ExperimentSpec*, eval::StudySpec*>;

// The experiment or study `name` of a compiled script (when `name` is empty, whichever the
// main file declares first), or monostate after printing an error (with the closest name).
[[nodiscard]] Target pick_target(compiler::CompileResult& compiled, const std::filesystem::path& file,
                                 const std::string& name);

// --runs, --generations, --seed and each --set as (key, value); nullopt after printing an
// error (a --set without `=`).
[[nodiscard]] std::optional<std::vector<std::pair<std::string, std::string>>> override_settings(const RunOptions& o);

// Applies the command-line overrides (--runs, --generations, --seed, --set); prints each
// problem (after `where`: `condition `x`: `), returns false if any.
bool apply_overrides(const RunOptions& o, eval::ExperimentSpec& spec, std::string_view where = {});

// Whether the campaign of `spec` fits in this machine's memory (runtime/eval/memory_need.hpp);
// prints what it needs and what there is when not. Asked before any directory is made.
bool fits_in_memory(const eval::ExperimentSpec& spec);

// The overrides a stored run started with (and its dependency cache), to apply again.
// Throws store::StoreError when `dir`'s database holds them damaged.
[[nodiscard]] RunOptions stored_overrides(const store::StoredExperiment& stored, const std::filesystem::path& dir);
// The generations `esc run --resume DIR --generations G` carried the stored run on to (the
// experiment alone, not what it depends on); nullopt when it never was. Throws
// store::StoreError when the database holds it damaged.
[[nodiscard]] std::optional<int> stored_carry_on(const store::StoredExperiment& stored, const std::filesystem::path& dir);

[[nodiscard]] std::vector<store::SourceFile> sources_of(const compiler::CompileResult& compiled);

}  // namespace esc::cli
