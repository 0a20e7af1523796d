// `esc bench`: the cost of a script's campaign (--campaign), or the paper's workloads
// timed (bench_workloads.cpp).
#include <algorithm>
#include <fstream>
#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <thread>
#include <variant>

#include <fmt/format.h>

#include "app/dependencies.hpp"
#include "bench/campaign_estimate.hpp"
#include "cli/bench.hpp"
#include "cli/commands.hpp"
#include "cli/load.hpp"
#include "cli/terminal_events.hpp"

namespace esc::cli {

namespace {

// Evolved behaviors hold no genome until `esc run` runs their experiments; for timing,
// zero weights of the right size do (the cost of a step does not depend on them).
void zero_evolved_genomes(control::ControllerSpec& c) {
  for (control::SupervisedBehavior& b : c.behaviors)
    if (auto* fixed = std::get_if<control::FixedController>(&b.what); fixed != nullptr && fixed->spec != nullptr) {
      auto sub = std::make_shared<control::ControllerSpec>(*fixed->spec);
      zero_evolved_genomes(*sub);
      if (fixed->genome.empty()) fixed->genome.assign(sub->genome_size(), 0.0);
      fixed->spec = std::move(sub);
    }
}

// The script's experiments, its studies' conditions (`STUDY/CONDITION`; a condition that is
// one of the script's experiments unchanged counts once), and every experiment they need
// first (evolved behaviors, start genomes), each once, those needed first before those that
// need them; one that a condition gives settings (`energy.generations 60`) as it will run,
// named with them (`energy[generations=60]`, `energy[stop.generations=10]`). Empty after printing an error.
std::optional<std::vector<eval::ExperimentSpec>> whole_campaign(const compiler::CompileResult& compiled) {
  std::vector<eval::ExperimentSpec> out;
  std::set<std::string> seen;
  bool ok = true;
  std::function<void(const eval::ExperimentSpec&)> add = [&](const eval::ExperimentSpec& e) {
    if (!seen.insert(e.name).second) return;
    for (const std::string& n : e.needs())
      for (const eval::ExperimentSpec& x : compiled.all_experiments) {
        if (x.name != n) continue;
        eval::ExperimentSpec given = x;
        try {
          app::apply_dependency_settings(given, e.dependency_settings, e.name);
        } catch (const app::Error& error) {   // each reported, the whole campaign checked
          print_error(error);
          ok = false;
        }
        std::string settings;
        for (const eval::DependencySetting& d : e.dependency_settings) {
          if (d.path.front() != n) continue;
          // Further down too (`energy[stop.generations=10]`): the experiment changes with it.
          std::string key;
          for (std::size_t i = 1; i < d.path.size(); ++i) key += d.path[i] + ".";
          settings += fmt::format("{}{}{}={}", settings.empty() ? "" : ",", key, d.key, d.value);
        }
        if (!settings.empty()) given.name = fmt::format("{}[{}]", n, settings);
        add(given);
      }
    out.push_back(e);
  };
  for (const eval::ExperimentSpec& e : compiled.experiments) add(e);
  for (const eval::StudySpec& s : compiled.studies)
    for (const eval::ConditionSpec& c : s.conditions) {
      if (c.settings.empty() && seen.count(c.experiment.name) != 0) continue;
      eval::ExperimentSpec x = c.experiment;
      x.name = s.name + "/" + c.name;
      add(x);
    }
  if (!ok) return std::nullopt;
  return out;
}

int campaign_command(const BenchOptions& o) {
  compiler::CompileResult compiled = load_script(o.campaign);
  if (!compiled.ok()) return kExitBadInput;
  std::optional<std::vector<eval::ExperimentSpec>> campaign = whole_campaign(compiled);
  if (!campaign) return kExitBadInput;
  std::vector<eval::ExperimentSpec>& experiments = *campaign;
  for (eval::ExperimentSpec& e : experiments)
    for (control::ControllerSpec& c : e.controllers) zero_evolved_genomes(c);
  const std::size_t cores = std::max(1U, std::thread::hardware_concurrency());
  fmt::print("measuring each controller on one core for {:.1f} s ...\n", o.min_time_s);
  const auto costs = bench::estimate_campaign(experiments, o.min_time_s);
  std::size_t arch = 10;   // a controller per body's architecture names each body's network
  for (const auto& c : costs) arch = std::max(arch, c.architecture.size());
  fmt::print("\n{:<30} {:<12} {:<{}} {:>12} {:>14} {:>12} {:>11}\n", "experiment", "controller", "arch", arch,
             "evaluations", "steps (max)", "steps/s/core", "core-hours");
  double core_seconds = 0.0;
  for (const auto& c : costs) {
    core_seconds += c.core_seconds();
    fmt::print("{:<30} {:<12} {:<{}} {:>12.0f} {:>14.0f} {:>12.0f} {:>11.2f}\n", c.experiment, c.controller,
               c.architecture, arch, c.evaluations, c.max_steps, c.steps_per_second, c.core_seconds() / 3600.0);
  }
  // Not a bound either way: epochs that end early (a collision, an empty accumulator) make a
  // run cheaper, evolved controllers that step slower than these genomes (more rays within
  // reach, more contacts) dearer; docs/paper-results.md compares it with measured campaigns.
  fmt::print("\ntotal: {:.2f} core-hours (every epoch at full length, at the rates measured here; epochs that end "
             "early make a run cheaper, evolved controllers that step slower dearer)\n",
             core_seconds / 3600.0);
  fmt::print("wall time: full-length evaluations scheduled as `esc run` schedules them, every worker at the "
             "one-core rate; and the share of a linear speed-up with evaluations as long as measured (they end early, "
             "so rounds wait longer for their last one). docs/performance.md gives measured speed-ups.\n");
  for (const std::size_t workers : std::set<std::size_t>{cores, 16, 64, 256}) {
    const bench::Schedule full = bench::schedule(experiments, costs, workers, bench::Lengths::Full);
    const bench::Schedule measured = bench::schedule(experiments, costs, workers, bench::Lengths::Measured);
    fmt::print("  {:>4} workers{:<22} {:>8.2f} h   {:.0f}% of linear; {:.0f}% with measured lengths\n", workers,
               workers == cores ? " (this machine)" : workers == 256 ? " (e.g. 16 ranks x 16)" : "",
               full.wall_seconds / 3600.0, 100.0 * full.efficiency(workers), 100.0 * measured.efficiency(workers));
  }
  fmt::print("machine: {}\n", cpu_model());
  return kExitOk;
}


}  // namespace

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown CPU";
}

int bench_command(const BenchOptions& o) {
  if (!o.campaign.empty()) return campaign_command(o);
  if (!o.profile.empty()) return bench_profile(o);
  // Google Benchmark's own arguments select its items: the fractions are then left out.
  if (o.benchmark_args.empty())
    if (const int status = bench_reference(o); status != kExitOk) return status;
  return bench_workloads(o);
}

}  // namespace esc::cli
