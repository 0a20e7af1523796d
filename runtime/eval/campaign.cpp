#include "runtime/eval/campaign.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "runtime/core/rng.hpp"
#include "runtime/eval/evaluator.hpp"
#include "runtime/evo/es.hpp"

namespace esc::eval {

namespace {

using Clock = std::chrono::steady_clock;
using Workers = tbb::enumerable_thread_specific<Evaluator>;

GenerationStats summarise(int generation, const std::vector<evo::Individual>& offspring,
                          std::int64_t steps, double seconds) {
  GenerationStats g;
  g.generation = generation;
  g.evaluations = static_cast<std::int64_t>(offspring.size());
  g.steps = steps;
  g.seconds = seconds;
  double sum = 0.0;
  g.best = offspring.front().fitness;
  for (const auto& i : offspring) {
    sum += i.fitness;
    g.best = std::max(g.best, i.fitness);
  }
  const auto n = static_cast<double>(offspring.size());
  g.mean = sum / n;
  double sq = 0.0;
  for (const auto& i : offspring) sq += (i.fitness - g.mean) * (i.fitness - g.mean);
  g.sd = offspring.size() > 1 ? std::sqrt(sq / (n - 1.0)) : 0.0;
  return g;
}

// Evaluates every individual in parallel; each result lands in its own slot, so the
// outcome does not depend on which worker ran what.
std::int64_t evaluate_all(const control::ControllerSpec& controller, std::vector<evo::Individual>& pop,
                          std::uint64_t seed, int generation, Workers& workers) {
  std::vector<std::int64_t> steps(pop.size(), 0);
  tbb::parallel_for(std::size_t{0}, pop.size(), [&](std::size_t i) {
    const std::uint64_t s = derive_seed(seed, {static_cast<std::uint64_t>(Stream::Evaluate),
                                               static_cast<std::uint64_t>(generation), i});
    const Evaluation e = workers.local().evaluate(controller, pop[i].genes, s);
    pop[i].fitness = e.fitness;
    steps[i] = e.steps;
  });
  return std::accumulate(steps.begin(), steps.end(), std::int64_t{0});
}

RunResult evolve_one(const ExperimentSpec& spec, const control::ControllerSpec& controller, int run,
                     Workers& workers, CampaignListener& listener) {
  const evo::EvolutionStrategy es(spec.es, controller.genome_size());
  RunResult result;
  result.run = run;
  result.seed = run_seed(spec.seed, run);
  Rng init(result.seed, {static_cast<std::uint64_t>(Stream::Init)});
  std::vector<evo::Individual> parents = es.initial(init);
  bool have_best = false;
  for (int g = 0; g < spec.es.generations; ++g) {
    const auto start = Clock::now();
    Rng breed(result.seed, {static_cast<std::uint64_t>(Stream::Breed), static_cast<std::uint64_t>(g)});
    std::vector<evo::Individual> offspring = es.breed(parents, breed);
    const std::int64_t steps = evaluate_all(controller, offspring, result.seed, g, workers);
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    result.generations.push_back(summarise(g, offspring, steps, seconds));
    for (const auto& ind : offspring) {
      if (!have_best || ind.fitness > result.best_fitness) {
        have_best = true;
        result.best_fitness = ind.fitness;
        result.best_genome = ind.genes;
      }
    }
    parents = es.select(parents, offspring);
    listener.generation_done(controller, run, result.generations.back());
  }
  return result;
}

}  // namespace

std::uint64_t run_seed(std::uint64_t master_seed, int run) noexcept {
  return derive_seed(master_seed, {static_cast<std::uint64_t>(Stream::RunSeed), static_cast<std::uint64_t>(run)});
}

CampaignResult run_campaign(const ExperimentSpec& spec, const CampaignOptions& options,
                            CampaignListener& listener) {
  CampaignResult result;
  result.experiment = spec.name;
  result.seed = spec.seed;
  const int threads = options.threads > 0 ? options.threads : tbb::info::default_concurrency();
  // Honour a thread count above the core count too (results do not depend on it).
  const tbb::global_control allow(tbb::global_control::max_allowed_parallelism,
                                  static_cast<std::size_t>(threads));
  tbb::task_arena arena(threads);
  Workers workers([&spec] { return Evaluator(spec); });
  for (const control::ControllerSpec& c : spec.controllers) {
    ControllerResult cr;
    cr.name = c.name;
    cr.architecture = c.architecture();
    cr.genome_size = c.genome_size();
    for (int run = 0; run < spec.runs; ++run) {
      arena.execute([&] { cr.runs.push_back(evolve_one(spec, c, run, workers, listener)); });
      listener.run_done(c, cr.runs.back());
    }
    result.controllers.push_back(std::move(cr));
  }
  return result;
}

}  // namespace esc::eval
