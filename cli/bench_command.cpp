#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <thread>
#include <variant>

#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include "bench/campaign_estimate.hpp"
#include "bench/workloads.hpp"
#include "cli/commands.hpp"
#include "cli/load.hpp"

namespace esc::cli {

namespace {

// The console report as usual, plus the counters kept for the closing summary.
class CollectingReporter final : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    benchmark::ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs)
      for (const auto& [name, counter] : r.counters) values[r.benchmark_name()][name] = counter.value;
  }
  std::map<std::string, std::map<std::string, double>> values;
};

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);)
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown CPU";
}

std::vector<int> thread_counts(int max_threads) {
  std::vector<int> t;
  for (int n = 1; n < max_threads; n *= 2) t.push_back(n);
  t.push_back(max_threads);
  return t;
}

const control::ControllerSpec* paper_sc(const eval::ExperimentSpec& e) {
  const control::ControllerSpec* found = nullptr;
  for (const auto& c : e.controllers)
    if (c.head == control::Head::Symbolic && (found == nullptr || c.architecture() == "8-14-6")) found = &c;
  return found;
}

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

// The script's experiments and every experiment they need first (evolved behaviors, start
// genomes), each once, those needed first before those that need them.
std::vector<eval::ExperimentSpec> whole_campaign(const compiler::CompileResult& compiled) {
  std::vector<eval::ExperimentSpec> out;
  std::set<std::string> seen;
  std::function<void(const eval::ExperimentSpec&)> add = [&](const eval::ExperimentSpec& e) {
    if (!seen.insert(e.name).second) return;
    for (const std::string& n : e.needs())
      for (const eval::ExperimentSpec& x : compiled.all_experiments)
        if (x.name == n) add(x);
    out.push_back(e);
  };
  for (const eval::ExperimentSpec& e : compiled.experiments) add(e);
  return out;
}

int campaign_command(const BenchOptions& o) {
  compiler::CompileResult compiled = load_script(o.campaign);
  if (!compiled.ok()) return kExitBadInput;
  std::vector<eval::ExperimentSpec> experiments = whole_campaign(compiled);
  for (eval::ExperimentSpec& e : experiments)
    for (control::ControllerSpec& c : e.controllers) zero_evolved_genomes(c);
  const std::size_t cores = std::max(1U, std::thread::hardware_concurrency());
  fmt::print("measuring each controller on one core for {:.1f} s ...\n", o.min_time_s);
  const auto costs = bench::estimate_campaign(experiments, o.min_time_s);
  fmt::print("\n{:<30} {:<12} {:<10} {:>12} {:>14} {:>12} {:>11}\n", "experiment", "controller", "arch",
             "evaluations", "steps (max)", "steps/s/core", "core-hours");
  double core_seconds = 0.0;
  for (const auto& c : costs) {
    core_seconds += c.core_seconds();
    fmt::print("{:<30} {:<12} {:<10} {:>12.0f} {:>14.0f} {:>12.0f} {:>11.2f}\n", c.experiment, c.controller,
               c.architecture, c.evaluations, c.max_steps, c.steps_per_second, c.core_seconds() / 3600.0);
  }
  fmt::print("\ntotal: {:.2f} core-hours at most (every epoch at full length; early epochs end sooner)\n",
             core_seconds / 3600.0);
  fmt::print("wall time at most: full-length evaluations scheduled as `esc run` schedules them, every worker at the "
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


// The paper's two workloads: obstacle avoidance with the 8-14-6 symbolic controller, and
// the energy experiment with the 17-5-2 Elman classical controller (IR and light sensors,
// the accumulator, a recharge zone drawn at random every epoch).
struct PaperWorkload {
  std::string script;        // under experiments/
  std::string controller;    // empty: the 8-14-6 symbolic controller
  std::string what;          // how the line is labelled
  compiler::CompileResult compiled;
  const eval::ExperimentSpec* experiment = nullptr;
  const control::ControllerSpec* controller_spec = nullptr;
};

bool load_workload(PaperWorkload& w) {
  const std::filesystem::path script = std::filesystem::path(ESC_STDLIB_DIR) / w.script;
  w.compiled = load_script(script);
  if (!w.compiled.ok() || w.compiled.experiments.empty()) return false;
  w.experiment = &w.compiled.experiments.front();
  for (const auto& c : w.experiment->controllers)
    if (c.name == w.controller) w.controller_spec = &c;
  if (w.controller.empty()) w.controller_spec = paper_sc(*w.experiment);
  if (w.controller_spec == nullptr)
    fmt::print(stderr, "esc: error: {} has no controller `{}` to benchmark\n", script.string(), w.controller);
  return w.controller_spec != nullptr;
}

void print_workload(const PaperWorkload& w, const CollectingReporter& reporter, const std::vector<int>& counts) {
  const std::string name = fmt::format("{}/{}", w.experiment->name, w.controller_spec->name);
  const auto one = reporter.values.find("step/" + name);
  if (one != reporter.values.end())
    fmt::print("{} ({} {}, inertia {}): {:.0f} control steps/s per core ({})\n", name,
               w.controller_spec->architecture(), w.controller_spec->head == control::Head::Symbolic ? "symbolic" : "classical",
               w.experiment->robot.motor.inertia ? "on" : "off", one->second.at("steps/s"), w.what);
  const auto base = reporter.values.find(fmt::format("threads/{}/1/real_time", name));
  if (base == reporter.values.end()) return;
  for (int t : counts) {
    const auto it = reporter.values.find(fmt::format("threads/{}/{}/real_time", name, t));
    if (it == reporter.values.end()) continue;
    fmt::print("{:>3} thread{}: {:>9.0f} steps/s  {:>7.1f} evals/s  speed-up {:.2f}x\n", t, t == 1 ? " " : "s",
               it->second.at("steps/s"), it->second.at("evals/s"), it->second.at("steps/s") / base->second.at("steps/s"));
  }
}

}  // namespace

int bench_command(const BenchOptions& o) {
  if (!o.campaign.empty()) return campaign_command(o);
  std::vector<PaperWorkload> workloads(2);
  workloads[0].script = "paper/obstacle_avoidance.esc";
  workloads[0].what = "IR, physics, network, fitness";
  workloads[1].script = "paper/energy.esc";
  workloads[1].controller = "CC";
  workloads[1].what = "IR, light, energy, recharge zone, physics, Elman network, fitness";
  for (PaperWorkload& w : workloads)
    if (!load_workload(w)) return kExitBadInput;
  const int max_threads = o.max_threads > 0 ? o.max_threads : static_cast<int>(std::thread::hardware_concurrency());
  const std::vector<int> counts = thread_counts(std::max(1, max_threads));
  for (const PaperWorkload& w : workloads) bench::register_workload({w.experiment, w.controller_spec}, counts);

  std::vector<std::string> args = {"esc bench", fmt::format("--benchmark_min_time={}", o.min_time_s)};
  args.insert(args.end(), o.benchmark_args.begin(), o.benchmark_args.end());
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  int argc = static_cast<int>(argv.size());
  benchmark::Initialize(&argc, argv.data());
  if (benchmark::ReportUnrecognizedArguments(argc, argv.data())) return kExitUsage;
  CollectingReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();

  fmt::print("\nmachine: {}, {} hardware threads\n", cpu_model(), std::thread::hardware_concurrency());
  for (const PaperWorkload& w : workloads) print_workload(w, reporter, counts);
  for (const char* size : {"15", "50", "150"}) {
    const auto flat = reporter.values.find(fmt::format("BM_GpFlat/{}", size));
    const auto rec = reporter.values.find(fmt::format("BM_GpRecursive/{}", size));
    if (flat == reporter.values.end() || rec == reporter.values.end()) continue;
    fmt::print("GP trees of ~{} nodes: flat {:.1f}M evals/s, recursive {:.1f}M evals/s ({:.2f}x)\n", size,
               flat->second["items_per_second"] / 1e6, rec->second["items_per_second"] / 1e6,
               flat->second["items_per_second"] / rec->second["items_per_second"]);
  }
  return kExitOk;
}

}  // namespace esc::cli
