#include "cli/experiment_setup.hpp"

#include <utility>

#include <fmt/format.h>

#include "cli/load.hpp"
#include "compiler/names.hpp"

namespace esc::cli {

eval::ExperimentSpec* pick_experiment(compiler::CompileResult& compiled, const std::filesystem::path& file,
                                      const std::string& name) {
  if (compiled.experiments.empty()) {
    complain("esc: error: {} declares no experiment to run\n", file.string());
    return nullptr;
  }
  if (name.empty()) return &compiled.experiments.front();
  std::vector<std::string> names;
  for (auto& e : compiled.experiments) {
    if (e.name == name) return &e;
    names.push_back(e.name);
  }
  complain("esc: error: {} has no experiment `{}`; it declares {}\n", file.string(), name,
           compiler::quoted_list(names, " and "));
  if (const auto near = compiler::closest(name, names)) complain("help: did you mean `{}`?\n", *near);
  return nullptr;
}

bool apply_overrides(const RunOptions& o, eval::ExperimentSpec& spec) {
  std::vector<std::pair<std::string, std::string>> settings;
  if (o.runs) settings.emplace_back("runs", std::to_string(*o.runs));
  if (o.generations) settings.emplace_back("generations", std::to_string(*o.generations));
  if (o.seed) settings.emplace_back("seed", std::to_string(*o.seed));
  for (const std::string& kv : o.settings) {
    const auto eq = kv.find('=');
    if (eq == std::string::npos || eq == 0) {
      complain("esc: error: --set expects KEY=VALUE, got `{}`\n", kv);
      return false;
    }
    settings.emplace_back(kv.substr(0, eq), kv.substr(eq + 1));
  }
  bool ok = true;
  for (const auto& [key, value] : settings) {
    const std::string error = compiler::apply_setting(spec, key, value);
    if (!error.empty()) {
      complain("esc: error: {}={}: {}\n", key, value, error);
      ok = false;
    }
  }
  return ok;
}

RunOptions stored_overrides(const store::StoredExperiment& stored, const std::filesystem::path& dir) {
  RunOptions o;
  try {
    const auto& ov = stored.overrides;
    if (ov.contains("runs")) o.runs = ov["runs"].get<int>();
    if (ov.contains("generations")) o.generations = ov["generations"].get<int>();
    if (ov.contains("seed")) o.seed = ov["seed"].get<std::uint64_t>();
    if (ov.contains("set")) o.settings = ov["set"].get<std::vector<std::string>>();
    if (ov.contains("cache")) o.cache = ov["cache"].get<std::string>();
  } catch (const nlohmann::json::exception& e) {
    throw store::StoreError(fmt::format("{} is damaged: unreadable command-line settings ({})", dir.string(), e.what()));
  }
  return o;
}

std::vector<store::SourceFile> sources_of(const compiler::CompileResult& compiled) {
  std::vector<store::SourceFile> sources;
  for (const auto& [name, text] : compiled.sources) sources.push_back({name, text});
  return sources;
}

}  // namespace esc::cli
