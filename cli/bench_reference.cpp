// `esc bench`'s fractions: each paper workload against its plain reference, and the
// simulator pressed against a wall against the same simulator in free space, each pair
// timed in alternation on one core (bench/reference.hpp); and `esc bench --profile`, one of
// those loops alone for a fixed number of items, for callgrind or perf.
#include <chrono>
#include <map>
#include <memory>
#include <stdexcept>

#include <fmt/format.h>

#include "bench/neat_cost.hpp"
#include "bench/plain_workloads.hpp"
#include "bench/reference.hpp"
#include "cli/bench.hpp"
#include "cli/bench_paper.hpp"
#include "cli/library_path.hpp"
#include "cli/load.hpp"
#include "compiler/names.hpp"
#include "runtime/evo/es/es.hpp"

namespace esc::cli {

namespace {

constexpr std::size_t kGenomes = 16;
constexpr int kRounds = 10;
// NEAT's cost over a run's first generations: its networks have begun to grow.
constexpr int kNeatGenerations = 20;

template <class Plain>
bench::StepLoop plain_loop(std::shared_ptr<Plain> plain, const std::vector<std::vector<double>>& genomes) {
  return [plain, &genomes](std::uint64_t i) { return plain->evaluate(genomes[i % genomes.size()], i).steps; };
}

// Every loop `esc bench` times, by the name --profile takes, with the genomes they share.
struct Loops {
  std::map<std::string, bench::StepLoop> by_name;
  std::vector<std::vector<double>> obstacle_genomes, energy_genomes, supervisor_genomes;

  explicit Loops(const PaperWorkloads& w) {
    const auto genomes = [](const PaperWorkload& p) {
      const auto& es = *p.experiment->settings_of<evo::EsSettings>(eval::ExperimentSpec::kDefaultNetworks);
      return bench::random_genomes(p.controller->genome_size(), kGenomes, es.lower, es.upper);
    };
    obstacle_genomes = genomes(w.obstacle);
    energy_genomes = genomes(w.energy);
    supervisor_genomes = genomes(w.supervisor);
    if (obstacle_genomes[0].size() != bench::plain::Obstacle::kGenomeSize ||
        energy_genomes[0].size() != bench::plain::Energy::kGenomeSize ||
        supervisor_genomes[0].size() != bench::plain::Supervisor::kGenomeSize)
      throw std::runtime_error("the shipped paper scripts no longer declare the networks the plain references hold");
    by_name["obstacle"] = bench::esc_loop(*w.obstacle.experiment, *w.obstacle.controller, obstacle_genomes);
    by_name["obstacle-plain"] =
        plain_loop(std::make_shared<bench::plain::Obstacle>(bench::plain_setup(*w.obstacle.experiment)), obstacle_genomes);
    by_name["energy"] = bench::esc_loop(*w.energy.experiment, *w.energy.controller, energy_genomes);
    by_name["energy-plain"] =
        plain_loop(std::make_shared<bench::plain::Energy>(bench::plain_setup(*w.energy.experiment)), energy_genomes);
    by_name["supervisor"] = bench::esc_loop(*w.supervisor.experiment, *w.supervisor.controller, supervisor_genomes);
    by_name["supervisor-plain"] = plain_loop(
        std::make_shared<bench::plain::Supervisor>(bench::plain_setup(*w.supervisor.experiment), w.behavior_genomes),
        supervisor_genomes);
    by_name["pressed"] = bench::simulator_loop(*w.energy.experiment, bench::Situation::Pressed);
    by_name["free"] = bench::simulator_loop(*w.energy.experiment, bench::Situation::Free);
  }
};

void print_fraction(const std::string& label, const bench::Fraction& f) {
  fmt::print("{:<52} {:>12.0f} {:>14.0f} {:>9.2f}   {:.2f}-{:.2f}\n", label, f.steps_per_s, f.reference_per_s, f.value(),
             f.lowest, f.highest);
}

// NEAT's own work beside the evaluations it serves, on the shipped NEAT maze experiment.
int print_neat_cost() {
  const std::filesystem::path script = standard_library_dir() / "lehman_stanley" / "mazes.esc";
  const compiler::CompileResult mazes = load_script(script);
  if (!mazes.ok()) return kExitBadInput;
  for (const eval::ExperimentSpec& x : mazes.experiments) {
    if (x.name != "medium_neat") continue;
    for (const control::ControllerSpec& c : x.controllers) {
      if (!c.is_graph()) continue;
      const bench::NeatCost cost = bench::measure_neat_cost(x, c, kNeatGenerations);
      const double per = 1000.0 / cost.generations;
      fmt::print("NEAT beside its evaluations ({} of {}: {} evaluations a generation, its first {} generations, "
                 "one core, thread CPU time):\n\n",
                 x.name, script.filename().string(), cost.evaluations / cost.generations, cost.generations);
      fmt::print("{:<52} {:>12.2f} ms a generation\n", "NEAT: breeding, speciation, scores (ask, tell)",
                 per * cost.neat_s);
      fmt::print("{:<52} {:>12.2f} ms a generation\n", "building each candidate's network", per * cost.build_s);
      fmt::print("{:<52} {:>12.2f} ms a generation\n", "evaluating them (simulation, network, fitness)",
                 per * cost.evaluate_s);
      fmt::print("{:<52} {:>12.2f}%   (networks of {:.2f} hidden nodes, {:.1f} links at the end)\n\n",
                 "NEAT and the building, of the evaluations' time", 100.0 * cost.fraction(), cost.hidden_nodes,
                 cost.enabled_links);
      return kExitOk;
    }
  }
  fmt::print(stderr, "esc: error: {} has no experiment `medium_neat` with a `neat(...)` controller to time\n",
             script.string());
  return kExitBadInput;
}

}  // namespace

int bench_reference(const BenchOptions& o) {
  const auto w = PaperWorkloads::load();
  if (w == nullptr) return kExitBadInput;
  const Loops loops(*w);
  const double seconds = 2 * o.min_time_s;
  fmt::print("esc against plain C++ of the same workload (bench/plain_*.cpp; docs/performance.md says what they leave "
             "out),\neach pair alternated on one core in {} rounds of {:.2f} s of thread CPU time each:\n\n",
             kRounds, seconds / kRounds);
  fmt::print("{:<52} {:>12} {:>14} {:>9}   {}\n", "workload", "esc steps/s", "plain steps/s", "fraction", "rounds");
  for (const PaperWorkload* p : {&w->obstacle, &w->energy, &w->supervisor}) {
    const std::string name = p == &w->obstacle ? "obstacle" : p == &w->energy ? "energy" : "supervisor";
    print_fraction(p->label, bench::interleave(loops.by_name.at(name), loops.by_name.at(name + "-plain"), seconds, kRounds));
  }
  fmt::print("\nthe simulator alone (8 IR readings and World::step), pressed against a wall against circling in free "
             "space:\n\n");
  fmt::print("{:<52} {:>12} {:>14} {:>9}   {}\n", "", "pressed", "free", "fraction", "rounds");
  print_fraction("contact-heavy stepping / free-space stepping",
                 bench::interleave(loops.by_name.at("pressed"), loops.by_name.at("free"), seconds, kRounds));
  fmt::print("\n");
  return print_neat_cost();
}

int bench_profile(const BenchOptions& o) {
  const auto w = PaperWorkloads::load();
  if (w == nullptr) return kExitBadInput;
  const Loops loops(*w);
  const auto loop = loops.by_name.find(o.profile);
  if (loop == loops.by_name.end()) {
    std::vector<std::string> names;
    for (const auto& [name, unused] : loops.by_name) names.push_back(name);
    fmt::print(stderr, "esc: error: no loop `{}` to profile\n", o.profile);
    if (const auto near = compiler::closest(o.profile, names)) fmt::print(stderr, "help: did you mean `{}`?\n", *near);
    fmt::print(stderr, "help: the loops are {}\n", compiler::quoted_list(names));
    return kExitUsage;
  }
  std::int64_t steps = 0;
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < o.evaluations; ++i) steps += loop->second(static_cast<std::uint64_t>(i));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  fmt::print("{}: {} items, {} control steps in {:.3f} s ({:.0f} steps/s)\n", o.profile, o.evaluations, steps, seconds,
             static_cast<double>(steps) / seconds);
  return kExitOk;
}

}  // namespace esc::cli
