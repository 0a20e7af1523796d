#pragma once
// Lowers `study` declarations to eval::StudySpec: the conditions (whole experiments,
// experiments with settings changed, the points of a sweep: the grid of several settings'
// listed values), the study's `runs` and `seed`, every condition's settings read and
// checked by the `--set` tables (setting_keys.hpp) at the values written (a setting of an
// experiment the condition depends on, `energy.generations`, checked on that experiment),
// and the names and directories of the conditions (unique, usable as file names).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "compiler/ast.hpp"
#include "compiler/lower_experiment.hpp"
#include "compiler/resolver.hpp"
#include "compiler/sink.hpp"
#include "runtime/eval/study.hpp"

namespace esc::compiler {

class StudyLowering {
 public:
  StudyLowering(Sink& sink, Resolver& names, ExperimentLowering& experiments)
      : sink_(sink), names_(names), experiments_(experiments) {}

  // Nullopt when the study is wrong (reported).
  [[nodiscard]] std::optional<eval::StudySpec> lower(const ast::StudyDecl& d);

 private:
  // What every condition starts from: the study's `runs` (when given) and `seed`.
  struct Common {
    std::optional<int> runs;
    std::uint64_t seed = 1;
  };
  // The experiment `ref` names, lowered, with the study's runs and seed; null when wrong
  // (reported, then or when the experiment was lowered: `broken_reference_` remembers it).
  std::optional<eval::ExperimentSpec> base(const ast::Name& ref, const Common& common);
  // `condition NAME = EXP { KEY VALUE ... }`.
  std::optional<eval::ConditionSpec> condition(const ast::StudyItem& item, const Common& common);
  // `sweep EXP { KEY [V1, V2, ...] ... }`: one condition per point of the grid.
  std::vector<eval::ConditionSpec> sweep(const ast::StudyItem& item, const Common& common, int index);
  // Sets `setting`'s key to `value` in `spec` (a study may not set `seed`). False when refused.
  bool apply(eval::ExperimentSpec& spec, const ast::StudySetting& setting, const ast::Value& value);
  // Whether `key` names an experiment first (`energy.generations`), not a group of settings.
  [[nodiscard]] bool is_dependency_key(std::string_view key) const;
  // `energy.generations 60`: records a setting of an experiment `spec` depends on, its value
  // read as that experiment's; `written_above` is the part of the key already stripped on the
  // way down (`energy.` for `energy.stop.generations`), so that errors name the key as written.
  // False when refused.
  bool apply_to_dependency(eval::ExperimentSpec& spec, const ast::StudySetting& setting, const ast::Value& value,
                           const std::string& written_above = {});
  // The settings recorded for each experiment `spec` depends on, checked together on it (as
  // the runtime applies them), reported at `where`. False when one fails.
  bool check_dependency_settings(const eval::ExperimentSpec& spec, const SourceRange& where);
  // Reports a key given twice in one condition or sweep, or `robot.KEY` with `bodyN.KEY`.
  bool unique_keys(const std::vector<ast::StudySetting>& settings);

  Sink& sink_;
  Resolver& names_;
  ExperimentLowering& experiments_;
  // Whether the study being lowered names an experiment that is wrong: its conditions are
  // then missing for a reason already reported, and "has no conditions" would be a second
  // error for one mistake.
  bool broken_reference_ = false;
};

}  // namespace esc::compiler
