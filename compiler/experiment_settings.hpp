#pragma once
// The experiment's own settings: `epochs`, `steps`, `runs` and `seed` (items of an
// experiment block, `--set KEY=VALUE` and resolved settings under one name), and
// `generations` (`--set generations`, for the ES and the GP alike; scripts give it in
// `evolve es(...)` / `evolve gp(...)`), `stop_at_success` (`stop at success` in a script),
// `members_every`, `networks` and a group's `roles`, `formation`, `formation_spacing` and
// `formation_at` (`formation line 10cm` in a script). Each row reads and checks its value.
#include <string>
#include <string_view>
#include <vector>

#include "compiler/ast.hpp"
#include "compiler/sink.hpp"
#include "runtime/eval/experiment.hpp"

namespace esc::compiler {

struct ExperimentSetting {
  std::string_view key;
  std::string_view summary;
  // Reads `v`, checks it and stores it in `x`; reports at `v`.
  bool (*read)(const ExperimentSetting& s, eval::ExperimentSpec& x, const ast::Value& v, Sink& sink);
  std::string (*text)(const eval::ExperimentSpec& x);   // resolved settings
};

[[nodiscard]] const std::vector<ExperimentSetting>& experiment_settings();
// The formations' words, in sim::FormationKind's order: random, line, circle, at.
[[nodiscard]] const std::vector<std::string>& formation_words();
[[nodiscard]] const ExperimentSetting* find_experiment_setting(std::string_view key);

}  // namespace esc::compiler
