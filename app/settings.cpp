#include "app/settings.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "app/error.hpp"
#include "compiler/compiler.hpp"
#include "compiler/names.hpp"
#include "compiler/setting_keys.hpp"
#include "runtime/core/seed_text.hpp"
#include "runtime/eval/memory_need.hpp"
#include "runtime/store/seed_json.hpp"

namespace esc::app {

namespace {

// Index of the compared controller `name`, or nullopt.
std::optional<std::size_t> index_of(const eval::ExperimentSpec& spec, const std::string& name) {
  for (std::size_t i = 0; i < spec.controllers.size(); ++i)
    if (spec.controllers[i].name == name) return i;
  return std::nullopt;
}

// Dependencies whose targets point into the kept controllers, the indices renumbered.
std::vector<eval::Dependency> kept_dependencies(const std::vector<eval::Dependency>& all,
                                                const std::vector<std::size_t>& kept) {
  std::vector<eval::Dependency> out;
  for (const eval::Dependency& d : all) {
    eval::Dependency k{d.experiment, d.controller, {}};
    for (const auto& [controller, behavior] : d.targets) {
      const auto at = std::find(kept.begin(), kept.end(), controller);
      if (at != kept.end()) k.targets.emplace_back(static_cast<std::size_t>(at - kept.begin()), behavior);
    }
    if (!k.targets.empty()) out.push_back(std::move(k));
  }
  return out;
}

}  // namespace

std::vector<std::pair<std::string, std::string>> setting_pairs(const Overrides& o) {
  std::vector<std::pair<std::string, std::string>> settings;
  if (o.runs) settings.emplace_back("runs", std::to_string(*o.runs));
  if (o.generations) settings.emplace_back("generations", std::to_string(*o.generations));
  if (o.seed) settings.emplace_back("seed", seed_text(*o.seed));
  for (const std::string& kv : o.set) {
    const auto eq = kv.find('=');
    if (eq == std::string::npos || eq == 0)
      throw Error(ErrorKind::Setting, fmt::format("--set expects KEY=VALUE, got `{}`", kv));
    settings.emplace_back(kv.substr(0, eq), kv.substr(eq + 1));
  }
  return settings;
}

Overrides for_dependencies(Overrides o) {
  std::erase_if(o.set, [](const std::string& kv) {
    const auto eq = kv.find('=');
    return eq != std::string::npos && compiler::body_key(compiler::trimmed(kv.substr(0, eq))).has_value();
  });
  return o;
}

void apply_settings(const Overrides& o, eval::ExperimentSpec& spec, std::string_view where) {
  // Together, as a script's items are (`--set formation=line --set formation_spacing=10cm`):
  // each setting that cannot be set names itself; settings that cannot stand together are
  // named together.
  const auto pairs = setting_pairs(o);
  const compiler::SettingsRefusal refusal = compiler::apply_settings_together(spec, pairs);
  Problems problems;
  for (const auto& [i, why] : refusal.settings)
    problems.add(fmt::format("{}{}={}: {}", where, pairs[i].first, pairs[i].second, why));
  if (!refusal.together.empty()) {
    std::string named;
    for (const auto& [key, value] : pairs) named += fmt::format("{}{}={}", named.empty() ? "" : " ", key, value);
    problems.add(fmt::format("{}{}: {}", where, named, refusal.together));
  }
  problems.throw_if_any(ErrorKind::Setting);
}

void select_controllers(const std::vector<std::string>& names, eval::ExperimentSpec& spec, std::string_view where) {
  if (names.empty()) return;
  std::vector<std::string> compared;
  for (const auto& c : spec.controllers) compared.push_back(c.name);
  std::vector<std::size_t> kept;
  Problems problems;
  for (const std::string& name : names) {
    const auto i = index_of(spec, name);
    if (!i) {
      const auto near = compiler::closest(name, compared);
      problems.add(fmt::format("{}--controllers: experiment `{}` compares no controller `{}`; it compares {}", where,
                               spec.name, name, compiler::quoted_list(compared, ", ")),
                   near ? fmt::format("did you mean `{}`?", *near) : std::string());
    } else if (std::find(kept.begin(), kept.end(), *i) != kept.end()) {
      problems.add(fmt::format("{}--controllers names `{}` twice", where, name));
    } else {
      kept.push_back(*i);
    }
  }
  problems.throw_if_any(ErrorKind::Setting);
  std::vector<control::ControllerSpec> controllers;
  for (std::size_t i : kept) controllers.push_back(spec.controllers[i]);
  spec.dependencies = kept_dependencies(spec.dependencies, kept);
  spec.controllers = std::move(controllers);
}

void check_memory(const eval::ExperimentSpec& spec) {
  const std::string problem = eval::memory_problem(spec, true, eval::memory_limit());
  // One line: the message names the setting to lower.
  if (!problem.empty()) throw Error(ErrorKind::Memory, problem);
}

nlohmann::ordered_json to_json(const Overrides& o) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  if (o.runs) j["runs"] = *o.runs;
  if (o.generations) j["generations"] = *o.generations;
  if (o.seed) j["seed"] = store::seed_json(*o.seed);
  j["set"] = o.set;
  if (!o.controllers.empty()) j["controllers"] = o.controllers;
  // Where dependencies were run or reused, so that a resume finds them again.
  if (!o.cache.empty()) j["cache"] = std::filesystem::absolute(o.cache).lexically_normal().string();
  return j;
}

Overrides stored_overrides(const store::StoredExperiment& stored, const std::filesystem::path& dir) {
  return overrides_from_json(stored.overrides, dir);
}

Overrides overrides_from_json(const nlohmann::ordered_json& ov, const std::filesystem::path& dir) {
  Overrides o;
  try {
    if (ov.contains("runs")) o.runs = ov["runs"].get<int>();
    if (ov.contains("generations")) o.generations = ov["generations"].get<int>();
    if (ov.contains("seed")) o.seed = store::seed_from_json(ov["seed"]);
    if (ov.contains("set")) o.set = ov["set"].get<std::vector<std::string>>();
    if (ov.contains("controllers")) o.controllers = ov["controllers"].get<std::vector<std::string>>();
    if (ov.contains("cache")) o.cache = ov["cache"].get<std::string>();
  } catch (const std::exception& e) {   // JSON errors, a seed that is not one
    throw store::StoreError(fmt::format("{} is damaged: unreadable command-line settings ({})", dir.string(), e.what()));
  }
  return o;
}

std::optional<int> stored_carry_on(const store::StoredExperiment& stored, const std::filesystem::path& dir) {
  try {
    if (!stored.overrides.contains("carry_on")) return std::nullopt;
    return stored.overrides["carry_on"].get<int>();
  } catch (const nlohmann::json::exception& e) {
    throw store::StoreError(fmt::format("{} is damaged: unreadable generations carried on to ({})", dir.string(), e.what()));
  }
}

bool set_generations(eval::ExperimentSpec& spec, std::optional<int> generations) {
  return !generations || compiler::apply_setting(spec, "generations", std::to_string(*generations)).empty();
}

}  // namespace esc::app
