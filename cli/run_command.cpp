#include <chrono>
#include <ctime>
#include <iostream>
#include <vector>

#include <fmt/format.h>

#include "cli/commands.hpp"
#include "cli/load.hpp"
#include "cli/progress.hpp"
#include "runtime/eval/campaign.hpp"
#include "runtime/report/statistics.hpp"
#include "runtime/store/run_directory.hpp"

namespace esc::cli {

namespace {

void print_table(const eval::ExperimentSpec& spec, const eval::CampaignResult& result) {
  fmt::print("\n{}: {} run{} x {} generations, {} epochs x {} steps, seed {}\n", spec.name, spec.runs,
             spec.runs == 1 ? "" : "s", spec.es.generations, spec.epochs, spec.steps, spec.seed);
  fmt::print("{:<12} {:<14} {:>6}  {:>22}  {:>10}  {:>10}\n", "controller", "architecture", "genes",
             "best fitness mean ± sd", "median", "best run");
  for (const auto& c : result.controllers) {
    std::vector<double> best;
    for (const auto& r : c.runs) best.push_back(r.best_fitness);
    const report::Summary s = report::summarise(best);
    fmt::print("{:<12} {:<14} {:>6}  {:>12.1f} ± {:<7.1f}  {:>10.1f}  {:>10.1f}\n", c.name, c.architecture,
               c.genome_size, s.mean, s.sd, s.median, s.max);
  }
}

std::filesystem::path default_out(const std::string& experiment) {
  const std::time_t now = std::time(nullptr);
  std::tm tm{};
  localtime_r(&now, &tm);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &tm);
  return std::filesystem::path("runs") / fmt::format("{}-{}", experiment, stamp);
}

// Applies the command-line overrides; prints each problem, returns false if any.
bool apply_overrides(const RunOptions& o, eval::ExperimentSpec& spec) {
  std::vector<std::pair<std::string, std::string>> settings;
  if (o.runs) settings.emplace_back("runs", std::to_string(*o.runs));
  if (o.generations) settings.emplace_back("generations", std::to_string(*o.generations));
  if (o.seed) settings.emplace_back("seed", std::to_string(*o.seed));
  for (const std::string& kv : o.settings) {
    const auto eq = kv.find('=');
    if (eq == std::string::npos || eq == 0) {
      fmt::print(stderr, "esc: error: --set expects KEY=VALUE, got `{}`\n", kv);
      return false;
    }
    settings.emplace_back(kv.substr(0, eq), kv.substr(eq + 1));
  }
  bool ok = true;
  for (const auto& [key, value] : settings) {
    const std::string error = compiler::apply_setting(spec, key, value);
    if (!error.empty()) {
      fmt::print(stderr, "esc: error: {}={}: {}\n", key, value, error);
      ok = false;
    }
  }
  return ok;
}

}  // namespace

int run_command(const RunOptions& o) {
  compiler::CompileResult compiled = load_script(o.file);
  if (!compiled.ok()) return kExitBadInput;
  if (compiled.experiments.empty()) {
    fmt::print(stderr, "esc: error: {} declares no experiment to run\n", o.file.string());
    return kExitBadInput;
  }
  eval::ExperimentSpec* spec = &compiled.experiments.front();
  if (!o.experiment.empty()) {
    spec = nullptr;
    std::string names;
    for (auto& e : compiled.experiments) {
      if (e.name == o.experiment) spec = &e;
      names += (names.empty() ? "`" : ", `") + e.name + "`";
    }
    if (spec == nullptr) {
      fmt::print(stderr, "esc: error: {} has no experiment `{}`; it declares {}\n", o.file.string(),
                 o.experiment, names);
      return kExitBadInput;
    }
  }
  if (!apply_overrides(o, *spec)) return kExitBadInput;

  std::vector<store::SourceFile> sources;
  for (const auto& [name, text] : compiled.sources) sources.push_back({name, text});
  const std::filesystem::path out = o.out.empty() ? default_out(spec->name) : o.out;
  store::RunDirectory dir(out, *spec, sources);
  ProgressPrinter progress(*spec, dir);
  fmt::print("esc: running {} ({} controller{}, {} run{}, {} generations) into {}\n", spec->name,
             spec->controllers.size(), spec->controllers.size() == 1 ? "" : "s", spec->runs,
             spec->runs == 1 ? "" : "s", spec->es.generations, out.string());
  const eval::CampaignResult result = eval::run_campaign(*spec, {o.threads}, progress);
  dir.finish(result);
  print_table(*spec, result);
  fmt::print("\nresults: {}/summary.json\n", out.string());
  return kExitOk;
}

}  // namespace esc::cli
