// One run of a tree controller by generational genetic programming, with the guarantees of
// the ES loop: every random stream comes from (run seed, purpose, generation, individual),
// so a run is the same for any thread count, any sharing among MPI ranks, and when resumed
// after any generation. Generation 0 evaluates the initial population (Stream::Init);
// generation g > 0 breeds from generation g - 1 with Rng(seed, Breed, g) and evaluates the
// result. Every individual is evaluated, elites too: fitness is measured from random start
// poses, so an elite is judged on this generation's streams like everyone else.
#include <chrono>
#include <stdexcept>

#include "runtime/core/rng.hpp"
#include "runtime/eval/campaign_parts.hpp"
#include "runtime/evo/gp/codec.hpp"
#include "runtime/evo/gp/inline_actions.hpp"
#include "runtime/evo/gp/print.hpp"

namespace esc::eval::detail {

namespace {

// The tree as the body of a behavior that computes the same wheel commands, or "" when
// there is none (a Behavior tree; actions reading an arena's zones or lights).
std::string behavior_body(const control::ControllerSpec& controller, const evo::gp::Tree& tree) {
  const evo::gp::PrimitiveSet& set = *controller.primitives;
  if (set.root() == evo::gp::Type::Wheels) return evo::gp::to_script(tree, set);
  if (set.root() != evo::gp::Type::Action) return {};
  try {
    const evo::gp::InlinedTree inlined = evo::gp::inline_actions(tree, set, controller.actions);
    return evo::gp::to_script(inlined.tree, inlined.set);
  } catch (const std::invalid_argument&) {
    return {};
  }
}

}  // namespace

RunResult evolve_tree(const ExperimentSpec& spec, const control::ControllerSpec& controller, int run,
                      const RunState* from, const CampaignOptions& options, Evaluators& ev,
                      CampaignListener& listener) {
  if (!spec.gp)
    throw std::invalid_argument("tree controller '" + controller.name + "' is compared, but experiment '" +
                                spec.name + "' has no GP settings");
  const evo::gp::GeneticProgramming gp(*spec.gp, *controller.primitives);
  RunState st;
  if (from != nullptr) {
    st = *from;
  } else {
    st.run = run;
    st.seed = run_seed(spec.seed, run);
  }
  // A stored population must be one this script could have bred (the store keeps trees
  // without their primitive set).
  if (!st.generations.empty() && st.population.size() != static_cast<std::size_t>(spec.gp->population))
    throw std::invalid_argument("tree controller '" + controller.name + "': the state to resume from holds " +
                                std::to_string(st.population.size()) + " trees, the population is " +
                                std::to_string(spec.gp->population));
  for (const evo::gp::Individual& ind : st.population)
    if (const std::string why = evo::gp::check(ind.tree, *controller.primitives, controller.primitives->root());
        !why.empty())
      throw std::invalid_argument("tree controller '" + controller.name + "': a tree to resume from is not one of "
                                  "its primitive set: " + why);
  std::vector<double> fitness;
  for (int g = static_cast<int>(st.generations.size()); g < spec.gp->generations; ++g) {
    const auto start = std::chrono::steady_clock::now();
    std::vector<evo::gp::Individual> pop;
    if (g == 0) {
      Rng init(st.seed, {static_cast<std::uint64_t>(Stream::Init)});
      pop = gp.initial(init);
    } else {
      Rng breed(st.seed, {static_cast<std::uint64_t>(Stream::Breed), static_cast<std::uint64_t>(g)});
      pop = gp.breed(st.population, breed);
    }
    const std::int64_t steps = evaluate_all(
        pop.size(), st.seed, g, ev,
        [&](Evaluator& e, std::size_t i, std::uint64_t seed) { return e.evaluate(controller, pop[i].tree, seed); },
        fitness);
    for (std::size_t i = 0; i < pop.size(); ++i) pop[i].fitness = fitness[i];
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    st.generations.push_back(summarise(g, fitness, steps, seconds));
    if (const auto best = improve_best(st, g, fitness)) st.best_genome = evo::gp::encode(pop[*best].tree);
    st.population = std::move(pop);
    listener.generation_done(controller, run, st.generations.back());
    listener.checkpoint(controller, st);
  }
  const bool has_best = st.has_best;
  RunResult result = close_run(std::move(st));
  if (has_best) {
    const evo::gp::Tree best = evo::gp::decode(result.best_genome, *controller.primitives);
    result.best_tree = evo::gp::to_script(best, *controller.primitives);
    result.best_behavior = behavior_body(controller, best);
    replay_best(spec, controller, result, options, ev, listener,
                [&](Evaluator& e, std::uint64_t seed, TraceSink* sink) {
                  return e.evaluate(controller, best, seed, sink);
                });
  }
  return result;
}

}  // namespace esc::eval::detail
