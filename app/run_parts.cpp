#include "app/run_parts.hpp"

#include <algorithm>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "app/error.hpp"
#include "app/ranks.hpp"
#include "compiler/compiler.hpp"
#include "compiler/setting_keys.hpp"

namespace esc::app {

namespace {

std::string trimmed(std::string_view t) {
  while (!t.empty() && (t.front() == ' ' || t.front() == '\t')) t.remove_prefix(1);
  while (!t.empty() && (t.back() == ' ' || t.back() == '\t')) t.remove_suffix(1);
  return std::string(t);
}

// Refuses an override of a key no experiment has (once, not for the first condition), of a
// key the study varies, or of one it gives to an experiment its conditions depend on
// (`energy.generations 60`: the override would replace that too).
void vary_nothing_given(const Overrides& o, const eval::StudySpec& study) {
  const std::vector<std::string> varied = study.varied_keys();
  const auto given = [&](const std::string& k) -> const eval::DependencySetting* {
    for (const eval::ConditionSpec& c : study.conditions)
      for (const eval::DependencySetting& d : c.experiment.dependency_settings)
        if (d.key == k) return &d;
    return nullptr;
  };
  Problems problems;
  const std::vector<std::string> keys = compiler::setting_keys();
  for (const auto& [key, value] : setting_pairs(o)) {
    const std::string k = trimmed(key);
    // A key no experiment has is the command line's mistake, not a condition's.
    if (std::find(keys.begin(), keys.end(), k) == keys.end() && !study.conditions.empty()) {
      eval::ExperimentSpec probe = study.conditions.front().experiment;
      if (const std::string error = compiler::apply_setting(probe, key, value); !error.empty()) {
        problems.add(fmt::format("{}={}: {}", key, value, error));
        continue;
      }
    }
    if (const eval::DependencySetting* d = given(k)) {
      problems.add(fmt::format("{}={}: study `{}` gives `{}` to experiment `{}` in its conditions ({}.{} {}); the "
                               "command line's value would replace it (to shorten such a study, run its experiments "
                               "with --experiment)",
                               k, trimmed(value), study.name, k, d->path.back(), fmt::join(d->path, "."), d->key,
                               d->value));
      continue;
    }
    if (std::find(varied.begin(), varied.end(), k) == varied.end()) continue;
    problems.add(fmt::format("{}={}: study `{}` varies `{}` across its conditions; one value for all of them would "
                             "flatten it (to run one condition with another value, run its experiment with "
                             "--experiment and --set)",
                             k, trimmed(value), study.name, k));
  }
  problems.throw_if_any(ErrorKind::Setting);
}

}  // namespace

void apply_to_experiment(const Overrides& o, eval::ExperimentSpec& spec, std::string_view where) {
  apply_settings(o, spec, where);
  select_controllers(o.controllers, spec, where);
  check_memory(spec);
}

void apply_to_study(const Overrides& o, eval::StudySpec& study) {
  vary_nothing_given(o, study);
  apply_to_conditions(o, study);
}

void apply_to_conditions(const Overrides& o, eval::StudySpec& study) {
  for (eval::ConditionSpec& c : study.conditions) apply_to_experiment(o, c.experiment, fmt::format("condition `{}`: ", c.name));
  if (o.seed) study.seed = *o.seed;
}

std::vector<ConditionOutcome> run_conditions(const eval::StudySpec& study, const Execution& x,
                                             std::optional<store::StudyDirectory>& dir, const StoredStudy& stored,
                                             Events& events) {
  std::vector<ConditionOutcome> results;
  for (std::size_t i = 0; i < study.conditions.size(); ++i) {
    const eval::ConditionSpec& c = study.conditions[i];
    const store::StoredExperiment* before = stored.conditions != nullptr ? &(*stored.conditions)[i] : nullptr;
    // A finished condition runs again only when it is carried on.
    const bool carried_on = stored.carry_on != nullptr && (*stored.carry_on)[i];
    if (before != nullptr && before->finished() && !carried_on) {
      results.push_back({c.name, c.experiment, before->result()});
      continue;
    }
    const eval::ResumePoint point = before != nullptr ? (*stored.points)[i] : eval::ResumePoint{};
    tell(events, Note::Kind::Condition,
         fmt::format("condition {}/{} {}: {} ({} controller{}, {} run{}, {})", i + 1, study.conditions.size(), c.name,
                     c.experiment.name, c.experiment.controllers.size(),
                     c.experiment.controllers.size() == 1 ? "" : "s", c.experiment.runs,
                     c.experiment.runs == 1 ? "" : "s", generations_text(c.experiment)));
    std::optional<store::RunDirectory> run;
    if (dir) run.emplace(dir->open_condition(i, point));
    results.push_back({c.name, c.experiment,
                       run_campaign_into(c.experiment, c.name, campaign_options(x, before != nullptr ? &point : nullptr),
                                         run ? &*run : nullptr, generations_done(point), events)});
  }
  return results;
}

void tell(Events& events, Note note) {
  if (!follower_rank()) events.note(note);
}

void tell(Events& events, Note::Kind kind, std::string text, const std::filesystem::path& dir) {
  tell(events, Note{kind, std::move(text), dir});
}

std::string start_command(const std::filesystem::path& script, const std::string& target, const Overrides& o,
                          const std::filesystem::path& dir) {
  std::string command = fmt::format("esc run {} --experiment {}", script.string(), target);
  if (o.runs) command += fmt::format(" --runs {}", *o.runs);
  if (o.generations) command += fmt::format(" --generations {}", *o.generations);
  if (o.seed) command += fmt::format(" --seed {}", *o.seed);
  for (const std::string& kv : o.set) command += fmt::format(" --set {}", kv);
  if (!o.controllers.empty()) command += fmt::format(" --controllers {}", fmt::join(o.controllers, ","));
  if (!o.cache.empty()) command += fmt::format(" --cache {}", o.cache.string());
  return command + fmt::format(" --out {}", dir.string());
}

std::string names_of(const std::vector<std::string>& names) {
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

}  // namespace esc::app
