#include "bench/workloads.hpp"

#include <cstdint>
#include <string>

#include <benchmark/benchmark.h>
#include <fmt/format.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "runtime/core/rng.hpp"
#include "runtime/eval/evaluator.hpp"
#include "runtime/evo/es/es.hpp"

namespace esc::bench {

namespace {

// The paper's ES settings of the workload's experiment.
const evo::EsSettings& es_of(const Workload& w) {
  return *w.experiment->settings_of<evo::EsSettings>(eval::ExperimentSpec::kDefaultNetworks);
}

// Random genomes in the gene bounds: the controllers of an early generation.
std::vector<std::vector<double>> random_genomes(const Workload& w, std::size_t count) {
  Rng rng(12345);
  std::vector<std::vector<double>> g(count, std::vector<double>(w.controller->genome_size()));
  for (auto& genome : g)
    for (double& x : genome) x = rng.uniform(es_of(w).lower, es_of(w).upper);
  return g;
}

void one_core(benchmark::State& state, Workload w) {
  eval::Evaluator evaluator(*w.experiment);
  const auto genomes = random_genomes(w, 16);
  std::int64_t steps = 0;
  std::uint64_t i = 0;
  for (auto _ : state) {
    const auto e = evaluator.evaluate(*w.controller, genomes[i % genomes.size()], i);
    steps += e.steps;
    ++i;
  }
  state.counters["steps/s"] = benchmark::Counter(static_cast<double>(steps), benchmark::Counter::kIsRate);
}

void threads(benchmark::State& state, Workload w) {
  const int t = static_cast<int>(state.range(0));
  tbb::task_arena arena(t);
  tbb::enumerable_thread_specific<eval::Evaluator> workers([&] { return eval::Evaluator(*w.experiment); });
  // One generation of the experiment (lambda evaluations), as a run evaluates it.
  const auto batch = static_cast<std::size_t>(es_of(w).lambda);
  const auto genomes = random_genomes(w, batch);
  std::vector<std::int64_t> steps(batch, 0);
  std::int64_t total_steps = 0;
  std::int64_t evaluations = 0;
  std::uint64_t round = 0;
  for (auto _ : state) {
    arena.execute([&] {
      tbb::parallel_for(std::size_t{0}, batch, [&](std::size_t i) {
        steps[i] = workers.local().evaluate(*w.controller, genomes[i], round * batch + i).steps;
      });
    });
    for (auto s : steps) total_steps += s;
    evaluations += static_cast<std::int64_t>(batch);
    ++round;
  }
  state.counters["steps/s"] = benchmark::Counter(static_cast<double>(total_steps), benchmark::Counter::kIsRate);
  state.counters["evals/s"] = benchmark::Counter(static_cast<double>(evaluations), benchmark::Counter::kIsRate);
}

}  // namespace

void register_workload(const Workload& w, const std::vector<int>& thread_counts) {
  const std::string name = fmt::format("{}/{}", w.experiment->name, w.controller->name);
  benchmark::RegisterBenchmark(("step/" + name).c_str(), one_core, w)->Unit(benchmark::kMillisecond);
  auto* b = benchmark::RegisterBenchmark(("threads/" + name).c_str(), threads, w);
  for (int t : thread_counts) b->Arg(t);
  b->UseRealTime()->Unit(benchmark::kMillisecond);
}

}  // namespace esc::bench
