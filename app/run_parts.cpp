#include "app/run_parts.hpp"

#include <algorithm>
#include <optional>
#include <set>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "app/error.hpp"
#include "app/ranks.hpp"
#include "compiler/compiler.hpp"
#include "compiler/setting_keys.hpp"

namespace esc::app {

namespace {

using compiler::trimmed;

// Refuses an override of a key no experiment has (once, not for the first condition), or of
// one the study gives to an experiment its conditions depend on (`energy.generations 60`: the
// override would replace that too), or one body's setting against every body's, one from the
// study and one from the command line (`robot.emission` over a condition's `body2.emission`
// would override it, whether or not the conditions differ in it).
void refuse_unknown_or_given(const Overrides& o, const eval::StudySpec& study) {
  const auto given = [&](const std::string& k) -> const eval::DependencySetting* {
    for (const eval::ConditionSpec& c : study.conditions)
      for (const eval::DependencySetting& d : c.experiment.dependency_settings)
        if (d.key == k || compiler::overlapping_keys(k, d.key)) return &d;
    return nullptr;
  };
  const auto overlapped = [&](const std::string& k) -> std::optional<std::pair<std::string, std::string>> {
    for (const eval::ConditionSpec& c : study.conditions)
      for (const eval::ConditionSetting& s : c.settings)
        if (compiler::overlapping_keys(k, s.key)) return std::pair{c.name, s.key};
    return std::nullopt;
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
    // One body's setting does not reach dependencies (for_dependencies): it replaces nothing there.
    if (const eval::DependencySetting* d = compiler::body_key(k) ? nullptr : given(k))
      problems.add(fmt::format("{}={}: study `{}` gives `{}` to experiment `{}` in its conditions ({}.{} {}); the "
                               "command line's value would replace it (to shorten such a study, run its experiments "
                               "with --experiment)",
                               k, trimmed(value), study.name, d->key, d->path.back(), fmt::join(d->path, "."), d->key,
                               d->value));
    else if (const auto c = overlapped(k))
      problems.add(fmt::format("{}={}: condition `{}` of study `{}` sets `{}`, and `{}` would override it "
                               "(`robot.KEY` sets every body, `bodyN.KEY` one; to run one condition with another "
                               "value, run its experiment with --experiment and --set)",
                               k, trimmed(value), c->first, study.name, c->second, k));
  }
  problems.throw_if_any(ErrorKind::Setting);
}

// A resolved setting's value, or none where the experiment does not resolve it (`body2.X`
// only where body 2 differs from the first, `cmaes.*` only where CMA-ES evolves).
std::optional<std::string> resolved(const eval::ExperimentSpec& e, const std::string& key) {
  const auto it = e.resolved_settings.find(key);
  return it == e.resolved_settings.end() ? std::nullopt : std::optional(it->second);
}

// What a condition without `key` in its resolved settings has: a further body's setting is
// written only where it differs from the first body's; others only where they apply.
std::string unresolved(const std::string& key) {
  return key.starts_with("body") ? "as the first body" : "not set";
}

// Refuses overrides that would make two conditions alike in a resolved setting the study makes
// them differ in: one value for every condition would flatten what it compares without saying
// so. Two conditions of one experiment differ only by the study, in every key, the key given
// or another (`robot.emission` sets every body of a group, conditions apart in
// `body2.emission`; `generations` sets GP's too; `networks` drops `cmaes.*`). Conditions of
// two experiments differ by their declarations too (`generations` 100 and 20): there, only in
// the keys some condition sets. A key every condition sets alike (`generations 50` in each)
// flattens nothing and may be given.
void refuse_flattening(const Overrides& o, const eval::StudySpec& study) {
  std::set<std::string> set_by_conditions;
  for (const eval::ConditionSpec& c : study.conditions)
    for (const eval::ConditionSetting& s : c.settings) set_by_conditions.insert(s.key);
  std::vector<eval::ExperimentSpec> after;
  try {
    for (const eval::ConditionSpec& c : study.conditions) {
      after.push_back(c.experiment);
      apply_settings(o, after.back());
    }
  } catch (const Error&) {
    return;   // applying them for real reports it, naming the condition
  }
  const std::vector<std::pair<std::string, std::string>> given = setting_pairs(o);
  const auto given_as = [&](const std::string& key) {
    for (const auto& [k, v] : given)
      if (trimmed(k) == key) return fmt::format("{}={}", key, trimmed(v));
    std::vector<std::string> all;
    for (const auto& [k, v] : given) all.push_back(fmt::format("{}={}", trimmed(k), trimmed(v)));
    return fmt::format("{}", fmt::join(all, " "));
  };
  Problems problems;
  std::vector<std::string> flattened;
  for (std::size_t i = 0; i < study.conditions.size(); ++i)
    for (std::size_t j = i + 1; j < study.conditions.size(); ++j) {
      const eval::ExperimentSpec& a = study.conditions[i].experiment;
      const eval::ExperimentSpec& b = study.conditions[j].experiment;
      std::set<std::string> keys = set_by_conditions;
      if (a.name == b.name) {
        for (const auto& [k, v] : a.resolved_settings) keys.insert(k);
        for (const auto& [k, v] : b.resolved_settings) keys.insert(k);
      }
      for (const std::string& key : keys) {
        const auto va = resolved(a, key), vb = resolved(b, key);
        if (va == vb || resolved(after[i], key) != resolved(after[j], key)) continue;
        if (std::find(flattened.begin(), flattened.end(), key) != flattened.end()) continue;
        flattened.push_back(key);
        problems.add(fmt::format("{}: study `{}` varies `{}` across its conditions (`{}`: {}, `{}`: {}); one value "
                                 "for all of them would flatten it (to run one condition with another value, run its "
                                 "experiment with --experiment and --set)",
                                 given_as(key), study.name, key, study.conditions[i].name, va.value_or(unresolved(key)),
                                 study.conditions[j].name, vb.value_or(unresolved(key))));
      }
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
  refuse_unknown_or_given(o, study);
  refuse_flattening(o, study);
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
