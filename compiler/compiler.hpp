#pragma once
// Entry point of the compiler: script text in, checked experiments (runtime objects) and
// diagnostics out. Never throws for bad input: every problem is a Diagnostic.
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "compiler/diagnostic.hpp"
#include "runtime/eval/experiment.hpp"
#include "runtime/eval/study.hpp"

namespace esc::compiler {

struct CompileOptions {
  // Searched, in order, for an `import "path"` not found beside the importing file.
  // The CLI passes $ESC_PATH entries, then the shipped experiments/ directory.
  std::vector<std::filesystem::path> import_paths;
};

struct CompileResult {
  std::vector<Diagnostic> diagnostics;           // in source order, errors and warnings
  std::vector<eval::ExperimentSpec> experiments; // in declaration order; empty on error
  // Every experiment of every file read (imported ones included), for the dependencies of
  // evolved behaviors; empty on error.
  std::vector<eval::ExperimentSpec> all_experiments;
  std::vector<eval::StudySpec> studies;          // the main file's, in declaration order; empty on error
  // The main file's first experiment or study, whichever is declared first: what `esc run`
  // runs without `--experiment`.
  std::string first_declared;
  SourceMap sources;                             // text of every file read, for rendering
  [[nodiscard]] bool ok() const noexcept;        // no diagnostic of severity Error
};

[[nodiscard]] CompileResult compile_file(const std::filesystem::path& file, const CompileOptions& options);

// `name` is used in diagnostics and to resolve relative imports (its parent directory).
[[nodiscard]] CompileResult compile_source(std::string_view text, const std::filesystem::path& name,
                                           const CompileOptions& options);

// Overrides one setting of a compiled experiment, as `esc run --set KEY=VALUE` does: the
// same spellings, units and checks as in a script (`epochs=2`, `mu=10`, `selection=plus`,
// `min_sigma=1e-5`, `robot.inertia=off`, `robot.time_constant=50ms`, `arena.sweep_cell=5cm`,
// `gp.population=50`; every key in setting_keys.hpp), then the checks of the settings
// together, the runtime's rules for the robot and the arena included, so a spec it accepts
// never fails the World's validation. Keeps resolved_settings in step. Returns an error
// message (with a "did you mean" for a misspelled key) or an empty string on success; the
// experiment is unchanged on error.
[[nodiscard]] std::string apply_setting(eval::ExperimentSpec& experiment, std::string_view key,
                                        std::string_view value);
// Several at once, (key, value) in order, checked together once all are set (as a script's
// items are), as a study condition's settings of an experiment it depends on are applied.
[[nodiscard]] std::string apply_settings(eval::ExperimentSpec& experiment,
                                         const std::vector<std::pair<std::string, std::string>>& settings);
// The same, saying which settings could not be set (their index in `settings`, and why) and,
// when each could, why they cannot stand together (`formation=line` with no spacing). The
// experiment is unchanged unless nothing is refused.
struct SettingsRefusal {
  std::vector<std::pair<std::size_t, std::string>> settings;
  std::string together;
  [[nodiscard]] bool empty() const noexcept { return settings.empty() && together.empty(); }
};
[[nodiscard]] SettingsRefusal apply_settings_together(eval::ExperimentSpec& experiment,
                                                      const std::vector<std::pair<std::string, std::string>>& settings);

}  // namespace esc::compiler
