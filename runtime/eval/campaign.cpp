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
#include "runtime/dist/distribution.hpp"
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

// Where evaluations run: this process's threads, and the other MPI ranks if any.
struct Evaluators {
  Workers& workers;
  dist::Distribution& distribution;
  std::size_t chunk;   // evaluations a process takes at a time: its thread count
};

// Evaluates every individual in parallel; each result lands in its own slot, so the
// outcome does not depend on which worker or rank ran what.
std::int64_t evaluate_all(const control::ControllerSpec& controller, std::vector<evo::Individual>& pop,
                          std::uint64_t seed, int generation, Evaluators& ev) {
  constexpr std::size_t kWidth = 2;   // fitness, steps (exact as doubles below 2^53)
  std::vector<double> results(pop.size() * kWidth, 0.0);
  ev.distribution.run(pop.size(), kWidth, ev.chunk, results, [&](std::size_t first, std::size_t last) {
    tbb::parallel_for(first, last, [&](std::size_t i) {
      const Evaluation e =
          ev.workers.local().evaluate(controller, pop[i].genes, evaluation_seed(seed, generation, i));
      results[i * kWidth] = e.fitness;
      results[i * kWidth + 1] = static_cast<double>(e.steps);
    });
  });
  std::int64_t steps = 0;
  for (std::size_t i = 0; i < pop.size(); ++i) {
    pop[i].fitness = results[i * kWidth];
    steps += static_cast<std::int64_t>(results[i * kWidth + 1]);
  }
  return steps;
}

// Collects a traced evaluation and counts the steps each action acted on.
struct Recorder final : TraceSink {
  std::vector<TraceStep> steps;
  std::vector<std::int64_t> usage;
  void on_step(const TraceStep& t) override {
    steps.push_back(t);
    if (t.action >= 0 && static_cast<std::size_t>(t.action) < usage.size()) ++usage[static_cast<std::size_t>(t.action)];
  }
};

// The genome run `run` of controller `index` starts from (`start from` / `evaluate from`),
// or null when it starts from a random population.
const std::vector<double>* start_genome(const ExperimentSpec& spec, std::size_t index, int run) {
  if (!spec.start_from || index >= spec.start_from->genomes.size()) return nullptr;
  const auto& runs = spec.start_from->genomes[index];
  if (runs.empty()) return nullptr;
  return &runs[static_cast<std::size_t>(run) % runs.size()];
}

RunState fresh_state(const ExperimentSpec& spec, const evo::EvolutionStrategy& es, int run,
                     const std::vector<double>* start) {
  RunState st;
  st.run = run;
  st.seed = run_seed(spec.seed, run);
  if (start != nullptr) {
    st.parents = es.seeded(*start);
    return st;
  }
  Rng init(st.seed, {static_cast<std::uint64_t>(Stream::Init)});
  st.parents = es.initial(init);
  return st;
}

// Generation g's offspring. A run that starts from a stored genome keeps it unchanged as
// offspring 0 of generation 0, so that generation measures it in the new setting; a run
// that only evaluates it has that one offspring.
std::vector<evo::Individual> offspring_of(const ExperimentSpec& spec, const evo::EvolutionStrategy& es,
                                          const RunState& st, const std::vector<double>* start, int g) {
  if (start != nullptr && spec.start_from->evaluate_only) return {st.parents.front()};
  Rng breed(st.seed, {static_cast<std::uint64_t>(Stream::Breed), static_cast<std::uint64_t>(g)});
  std::vector<evo::Individual> offspring = es.breed(st.parents, breed);
  if (start != nullptr && g == 0) offspring.front() = st.parents.front();
  return offspring;
}

RunResult evolve_one(const ExperimentSpec& spec, std::size_t index, int run, const RunState* from,
                     const CampaignOptions& options, Evaluators& ev, CampaignListener& listener) {
  const control::ControllerSpec& controller = spec.controllers[index];
  const evo::EvolutionStrategy es(spec.es, controller.genome_size());
  const std::vector<double>* seed_genome = start_genome(spec, index, run);
  RunState st = from != nullptr ? *from : fresh_state(spec, es, run, seed_genome);
  for (int g = static_cast<int>(st.generations.size()); g < spec.generations(); ++g) {
    const auto start = Clock::now();
    std::vector<evo::Individual> offspring = offspring_of(spec, es, st, seed_genome, g);
    const std::int64_t steps = evaluate_all(controller, offspring, st.seed, g, ev);
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    st.generations.push_back(summarise(g, offspring, steps, seconds));
    for (std::size_t i = 0; i < offspring.size(); ++i) {
      if (!st.has_best || offspring[i].fitness > st.best_fitness) {
        st.has_best = true;
        st.best_fitness = offspring[i].fitness;
        st.best_genome = offspring[i].genes;
        st.best_generation = g;
        st.best_index = static_cast<int>(i);
      }
    }
    if (!spec.start_from || !spec.start_from->evaluate_only) st.parents = es.select(st.parents, offspring);
    listener.generation_done(controller, run, st.generations.back());
    listener.checkpoint(controller, st);
  }
  RunResult result;
  result.run = run;
  result.seed = st.seed;
  result.generations = std::move(st.generations);
  result.best_fitness = st.best_fitness;
  result.best_genome = std::move(st.best_genome);
  result.best_generation = st.best_generation;
  result.best_index = st.best_index;
  if (st.has_best) {
    // Replays the best evaluation (same genome, same stream): the fitness is the same, and
    // the trace says which action acted when.
    Recorder rec;
    rec.usage.assign(controller.choice_names().size(), 0);
    if (options.trace_best) rec.steps.reserve(static_cast<std::size_t>(spec.epochs) * static_cast<std::size_t>(spec.steps));
    if (options.trace_best || !rec.usage.empty()) {
      const std::uint64_t seed = evaluation_seed(result.seed, result.best_generation,
                                                 static_cast<std::size_t>(result.best_index));
      (void)ev.workers.local().evaluate(controller, result.best_genome, seed, &rec);
      result.action_usage = std::move(rec.usage);
      if (options.trace_best) listener.best_traced(controller, result, rec.steps);
    }
  }
  return result;
}

const RunResult* find_finished(const ResumePoint* resume, const std::string& controller, int run) {
  if (resume == nullptr) return nullptr;
  for (const auto& f : resume->finished)
    if (f.controller == controller && f.result.run == run) return &f.result;
  return nullptr;
}

const RunState* find_in_progress(const ResumePoint* resume, const std::string& controller, int run) {
  if (resume == nullptr) return nullptr;
  for (const auto& p : resume->in_progress)
    if (p.controller == controller && p.state.run == run) return &p.state;
  return nullptr;
}

}  // namespace

std::uint64_t evaluation_seed(std::uint64_t run_seed, int generation, std::size_t index) noexcept {
  return derive_seed(run_seed, {static_cast<std::uint64_t>(Stream::Evaluate), static_cast<std::uint64_t>(generation),
                                static_cast<std::uint64_t>(index)});
}

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
  dist::Distribution distribution;
  Evaluators ev{workers, distribution, static_cast<std::size_t>(threads)};
  for (std::size_t index = 0; index < spec.controllers.size(); ++index) {
    const control::ControllerSpec& c = spec.controllers[index];
    ControllerResult cr;
    cr.name = c.name;
    cr.architecture = c.architecture();
    cr.genome_size = c.genome_size();
    cr.choices = c.choice_names();
    for (int run = 0; run < spec.runs; ++run) {
      if (const RunResult* done = find_finished(options.resume, c.name, run)) {
        cr.runs.push_back(*done);
        continue;
      }
      const RunState* partial = find_in_progress(options.resume, c.name, run);
      arena.execute([&] { cr.runs.push_back(evolve_one(spec, index, run, partial, options, ev, listener)); });
      listener.run_done(c, cr.runs.back());
    }
    result.controllers.push_back(std::move(cr));
  }
  return result;
}

}  // namespace esc::eval
