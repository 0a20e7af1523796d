#include "runtime/eval/campaign.hpp"

#include <algorithm>
#include <chrono>

#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include "runtime/core/rng.hpp"
#include "runtime/eval/campaign_parts.hpp"
#include "runtime/eval/evaluator.hpp"
#include "runtime/evo/es.hpp"

namespace esc::eval {

namespace {

using Clock = std::chrono::steady_clock;
using detail::Evaluators;

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

RunResult evolve_one(const ExperimentSpec& spec, const control::ControllerSpec& controller, int run,
                     const RunState* from, const CampaignOptions& options, Evaluators& ev,
                     CampaignListener& listener) {
  const evo::EvolutionStrategy es(spec.es, controller.genome_size());
  const auto index = static_cast<std::size_t>(&controller - spec.controllers.data());
  const std::vector<double>* seed_genome = start_genome(spec, index, run);
  RunState st = from != nullptr ? *from : fresh_state(spec, es, run, seed_genome);
  std::vector<double> fitness;
  for (int g = static_cast<int>(st.generations.size()); g < spec.generations_for(controller); ++g) {
    const auto start = Clock::now();
    std::vector<evo::Individual> offspring = offspring_of(spec, es, st, seed_genome, g);
    const std::int64_t steps = detail::evaluate_all(
        offspring.size(), st.seed, g, ev,
        [&](Evaluator& e, std::size_t i, std::uint64_t seed) {
          return e.evaluate(controller, offspring[i].genes, seed);
        },
        fitness);
    for (std::size_t i = 0; i < offspring.size(); ++i) offspring[i].fitness = fitness[i];
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    st.generations.push_back(detail::summarise(g, fitness, steps, seconds));
    if (const auto best = detail::improve_best(st, g, fitness)) st.best_genome = offspring[*best].genes;
    if (!spec.start_from || !spec.start_from->evaluate_only) st.parents = es.select(st.parents, offspring);
    listener.generation_done(controller, run, st.generations.back());
    listener.checkpoint(controller, st);
  }
  const bool has_best = st.has_best;
  RunResult result = detail::close_run(std::move(st));
  if (has_best)
    detail::replay_best(spec, controller, result, options, ev, listener,
                        [&](Evaluator& e, std::uint64_t seed, TraceSink* sink) {
                          return e.evaluate(controller, result.best_genome, seed, sink);
                        });
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
  detail::Workers workers([&spec] { return Evaluator(spec); });
  dist::Distribution distribution;
  Evaluators ev{workers, distribution, static_cast<std::size_t>(threads)};
  for (const control::ControllerSpec& c : spec.controllers) {
    ControllerResult cr;
    cr.name = c.name;
    cr.architecture = c.architecture();
    cr.genome_size = spec.genome_size_of(c);
    cr.choices = c.choice_names();
    for (int run = 0; run < spec.runs; ++run) {
      if (const RunResult* done = find_finished(options.resume, c.name, run)) {
        cr.runs.push_back(*done);
        continue;
      }
      const RunState* partial = find_in_progress(options.resume, c.name, run);
      const auto evolve = c.is_tree() ? detail::evolve_tree : evolve_one;
      arena.execute([&] { cr.runs.push_back(evolve(spec, c, run, partial, options, ev, listener)); });
      listener.run_done(c, cr.runs.back());
    }
    result.controllers.push_back(std::move(cr));
  }
  return result;
}

}  // namespace esc::eval
