#pragma once
// The arena's settable lengths (`sweep_cell`, `reach_radius`): one table for arena blocks in
// scripts, `esc run --set arena.KEY=VALUE` and resolved settings; and the resolved-settings
// text of the whole arena (`arena.size`, `arena.zones`, ...).
#include <string>
#include <string_view>
#include <vector>

#include "compiler/ast.hpp"
#include "runtime/eval/experiment.hpp"

namespace esc::compiler {

struct ArenaSetting {
  std::string_view name;                               // in arena blocks; `--set arena.NAME`; `arena.NAME`
  std::vector<ast::ArenaLength> ast::ArenaDecl::*items;   // where the parser keeps it
  double sim::ArenaSpec::*value;
  std::string_view summary;
};

[[nodiscard]] const std::vector<ArenaSetting>& arena_settings();
[[nodiscard]] const ArenaSetting* find_arena_setting(std::string_view name);
[[nodiscard]] std::vector<std::string> arena_setting_names();

// Writes the `arena` and `arena.*` keys of resolved_settings.
void resolve_arena_settings(eval::ExperimentSpec& spec);

}  // namespace esc::compiler
