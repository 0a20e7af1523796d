// `esc bench` without --campaign: the paper's workloads and the maze timed with Google Benchmark
// (built with ESC_WITH_BENCHMARK; bench_workloads_missing.cpp stands in without it).
#include <map>
#include <string>
#include <thread>
#include <vector>

#include <unistd.h>

#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include "bench/workloads.hpp"
#include "cli/bench.hpp"
#include "cli/load.hpp"
#include "cli/library_path.hpp"

namespace esc::cli {

namespace {

// The console report as usual, plus the counters kept for the closing summary.
class CollectingReporter final : public benchmark::ConsoleReporter {
 public:
  // Coloured on a terminal only: piped or redirected, the report is plain text.
  CollectingReporter() : ConsoleReporter(isatty(STDOUT_FILENO) != 0 ? OO_ColorTabular : OO_Tabular) {}
  void ReportRuns(const std::vector<Run>& runs) override {
    benchmark::ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs)
      for (const auto& [name, counter] : r.counters) values[r.benchmark_name()][name] = counter.value;
  }
  std::map<std::string, std::map<std::string, double>> values;
};

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

// The paper's two workloads: obstacle avoidance with the 8-14-6 symbolic controller, and
// the energy experiment with the 17-5-2 Elman classical controller (IR and light sensors,
// the accumulator, a recharge zone drawn at random every epoch); and Lehman & Stanley's
// medium maze.
struct TimedWorkload {
  std::string script;           // under experiments/
  std::string experiment_name;  // empty: the first the script declares
  std::string controller;       // empty: the 8-14-6 symbolic controller
  std::string what;          // how the line is labelled
  compiler::CompileResult compiled;
  const eval::ExperimentSpec* experiment = nullptr;
  const control::ControllerSpec* controller_spec = nullptr;
};

bool load_workload(TimedWorkload& w) {
  const std::filesystem::path script = standard_library_dir() / w.script;
  w.compiled = load_script(script);
  if (!w.compiled.ok() || w.compiled.experiments.empty()) return false;
  w.experiment = &w.compiled.experiments.front();
  for (const auto& e : w.compiled.experiments)
    if (e.name == w.experiment_name) w.experiment = &e;
  for (const auto& c : w.experiment->controllers)
    if (c.name == w.controller) w.controller_spec = &c;
  if (w.controller.empty()) w.controller_spec = paper_sc(*w.experiment);
  if (w.controller_spec == nullptr)
    fmt::print(stderr, "esc: error: {} has no controller `{}` to benchmark\n", script.string(), w.controller);
  return w.controller_spec != nullptr;
}

void print_workload(const TimedWorkload& w, const CollectingReporter& reporter, const std::vector<int>& counts) {
  const std::string name = fmt::format("{}/{}", w.experiment->name, w.controller_spec->name);
  const auto one = reporter.values.find("step/" + name);
  const bool accelerating = w.experiment->robot.drive == sim::DriveKind::Acceleration;
  if (one != reporter.values.end())
    fmt::print("{} ({} {}, {}): {:.0f} control steps/s per core ({})\n", name, w.controller_spec->architecture(),
               w.controller_spec->head == control::Head::Symbolic ? "symbolic" : "classical",
               accelerating ? "acceleration drive" : w.experiment->robot.motor.inertia ? "inertia on" : "inertia off",
               one->second.at("steps/s"), w.what);
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

int bench_workloads(const BenchOptions& o) {
  std::vector<TimedWorkload> workloads(4);
  workloads[0].script = "paper/obstacle_avoidance.esc";
  workloads[0].what = "IR, physics, network, fitness";
  workloads[1].script = "paper/energy.esc";
  workloads[1].controller = "CC";
  workloads[1].what = "IR, light, energy, recharge zone, physics, Elman network, fitness";
  // Lehman & Stanley's medium maze (issue 30): the navigator's network in a maze of segment
  // walls, 400 steps an evaluation.
  workloads[2].script = "lehman_stanley/mazes.esc";
  workloads[2].controller = "navigator_net";
  workloads[2].what = "6 rangefinders, 4 goal radars, 11 walls, physics, network, fitness, 2 descriptors";
  // The same maze and network on the authors' own body (issue 44): the kinematic navigator.
  workloads[3].script = "lehman_stanley/navigator_mazes.esc";
  workloads[3].experiment_name = "medium_on_navigator";
  workloads[3].controller = "navigator_net";
  workloads[3].what = "the navigator: 6 rangefinders, 4 goal radars, 11 walls, kinematic, network, fitness, 2 descriptors";
  for (TimedWorkload& w : workloads)
    if (!load_workload(w)) return kExitBadInput;
  const int max_threads = o.max_threads > 0 ? o.max_threads : static_cast<int>(std::thread::hardware_concurrency());
  const std::vector<int> counts = thread_counts(std::max(1, max_threads));
  for (const TimedWorkload& w : workloads) bench::register_workload({w.experiment, w.controller_spec}, counts);

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
  for (const TimedWorkload& w : workloads) print_workload(w, reporter, counts);
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
