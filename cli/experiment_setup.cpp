#include "cli/experiment_setup.hpp"

#include <utility>

#include <fmt/format.h>

#include "cli/load.hpp"
#include "compiler/names.hpp"
#include "runtime/eval/memory_need.hpp"
#include "runtime/store/seed_json.hpp"

namespace esc::cli {

namespace {

// "FILE has no WHAT `name`; it declares ...", with the closest name declared.
void no_such(const std::filesystem::path& file, std::string_view what, const std::string& name,
             const std::string& declared, const std::vector<std::string>& names) {
  complain("esc: error: {} has no {} `{}`; it declares {}\n", file.string(), what, name, declared);
  if (const auto near = compiler::closest(name, names)) complain("help: did you mean `{}`?\n", *near);
}

template <class T>
std::vector<std::string> names_of(const std::vector<T>& declared) {
  std::vector<std::string> names;
  for (const T& x : declared) names.push_back(x.name);
  return names;
}

}  // namespace

eval::ExperimentSpec* pick_experiment(compiler::CompileResult& compiled, const std::filesystem::path& file,
                                      const std::string& name) {
  if (compiled.experiments.empty()) {
    complain("esc: error: {} declares no experiment to run\n", file.string());
    return nullptr;
  }
  if (name.empty()) return &compiled.experiments.front();
  for (auto& e : compiled.experiments)
    if (e.name == name) return &e;
  const std::vector<std::string> names = names_of(compiled.experiments);
  no_such(file, "experiment", name, compiler::quoted_list(names, " and "), names);
  return nullptr;
}

eval::ExperimentSpec* pick_stored_experiment(compiler::CompileResult& compiled, const std::filesystem::path& file,
                                             const std::string& name) {
  for (auto& e : compiled.all_experiments)
    if (e.name == name) return &e;
  const std::vector<std::string> names = names_of(compiled.all_experiments);
  no_such(file, "experiment", name, names.empty() ? "none" : compiler::quoted_list(names, " and "), names);
  return nullptr;
}

Target pick_target(compiler::CompileResult& compiled, const std::filesystem::path& file, const std::string& name) {
  const std::string wanted = name.empty() ? compiled.first_declared : name;
  if (wanted.empty()) {
    complain("esc: error: {} declares no experiment or study to run\n", file.string());
    return {};
  }
  for (auto& e : compiled.experiments)
    if (e.name == wanted) return &e;
  for (auto& s : compiled.studies)
    if (s.name == wanted) return &s;
  const std::vector<std::string> experiments = names_of(compiled.experiments), studies = names_of(compiled.studies);
  std::string declared = experiments.empty() ? "" : "experiments " + compiler::quoted_list(experiments, ", ");
  if (!studies.empty())
    declared += (declared.empty() ? "studies " : " and studies ") + compiler::quoted_list(studies, ", ");
  std::vector<std::string> all = experiments;
  all.insert(all.end(), studies.begin(), studies.end());
  no_such(file, "experiment or study", wanted, declared.empty() ? "none" : declared, all);
  return {};
}

std::optional<std::vector<std::pair<std::string, std::string>>> override_settings(const RunOptions& o) {
  std::vector<std::pair<std::string, std::string>> settings;
  if (o.runs) settings.emplace_back("runs", std::to_string(*o.runs));
  if (o.generations) settings.emplace_back("generations", std::to_string(*o.generations));
  if (o.seed) settings.emplace_back("seed", seed_text(*o.seed));
  for (const std::string& kv : o.settings) {
    const auto eq = kv.find('=');
    if (eq == std::string::npos || eq == 0) {
      complain("esc: error: --set expects KEY=VALUE, got `{}`\n", kv);
      return std::nullopt;
    }
    settings.emplace_back(kv.substr(0, eq), kv.substr(eq + 1));
  }
  return settings;
}

bool apply_overrides(const RunOptions& o, eval::ExperimentSpec& spec, std::string_view where) {
  const auto settings = override_settings(o);
  if (!settings) return false;
  bool ok = true;
  for (const auto& [key, value] : *settings) {
    const std::string error = compiler::apply_setting(spec, key, value);
    if (!error.empty()) {
      complain("esc: error: {}{}={}: {}\n", where, key, value, error);
      ok = false;
    }
  }
  return ok;
}

bool fits_in_memory(const eval::ExperimentSpec& spec) {
  const std::string problem = eval::memory_problem(spec, true, eval::memory_limit());
  if (problem.empty()) return true;
  complain("esc: error: {}\nhelp: lower lambda (or the GP population, max_size, runs, epochs x steps), or run on a "
           "machine with more memory\n",
           problem);
  return false;
}

RunOptions stored_overrides(const store::StoredExperiment& stored, const std::filesystem::path& dir) {
  RunOptions o;
  try {
    const auto& ov = stored.overrides;
    if (ov.contains("runs")) o.runs = ov["runs"].get<int>();
    if (ov.contains("generations")) o.generations = ov["generations"].get<int>();
    if (ov.contains("seed")) o.seed = store::seed_from_json(ov["seed"]);
    if (ov.contains("set")) o.settings = ov["set"].get<std::vector<std::string>>();
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

std::vector<store::SourceFile> sources_of(const compiler::CompileResult& compiled) {
  std::vector<store::SourceFile> sources;
  for (const auto& [name, text] : compiled.sources) sources.push_back({name, text});
  return sources;
}

}  // namespace esc::cli
