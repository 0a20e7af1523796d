#include "bench/neat_cost.hpp"

#include <stdexcept>
#include <vector>

#include "bench/cpu_time.hpp"
#include "runtime/control/controller.hpp"
#include "runtime/eval/evaluator.hpp"
#include "runtime/evo/registry.hpp"

namespace esc::bench {

NeatCost measure_neat_cost(const eval::ExperimentSpec& experiment, const control::ControllerSpec& controller,
                           int generations) {
  if (!controller.is_graph()) throw std::invalid_argument("the NEAT cost is measured on a `neat(...)` controller");
  const eval::Evolution evolution = experiment.evolution_of(controller);
  evo::Problem problem = experiment.problem_of(controller);
  problem.seed = 1;
  const auto optimizer = evolution.algorithm->make(
      evolution.settings.has_value() ? evolution.settings : evolution.algorithm->defaults(), problem);
  eval::Evaluator evaluator(experiment);
  NeatCost cost;
  std::uint64_t seed = 0;
  for (int g = 0; g < generations; ++g) {
    double t = thread_cpu_seconds();
    const std::vector<evo::Genome> candidates = optimizer->ask(g);
    cost.neat_s += thread_cpu_seconds() - t;

    t = thread_cpu_seconds();
    for (const evo::Genome& genome : candidates) {
      const control::Controller built(controller, genome);
      (void)built;
    }
    const double build = thread_cpu_seconds() - t;
    cost.build_s += build;

    std::vector<evo::Outcome> outcomes(candidates.size());
    t = thread_cpu_seconds();
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      const eval::Evaluation e = evaluator.evaluate(controller, candidates[i], ++seed);
      outcomes[i].objectives = {e.fitness};
      outcomes[i].descriptors = e.descriptors;
    }
    cost.evaluate_s += thread_cpu_seconds() - t - build;
    cost.evaluations += static_cast<std::int64_t>(candidates.size());

    t = thread_cpu_seconds();
    optimizer->tell(outcomes);
    cost.neat_s += thread_cpu_seconds() - t;

  }
  // NEAT's own means over the last generation told.
  for (const evo::Metric& m : optimizer->metrics()) {
    if (m.name == "hidden_nodes") cost.hidden_nodes = m.value;
    if (m.name == "enabled_links") cost.enabled_links = m.value;
  }
  cost.generations = generations;
  return cost;
}

}  // namespace esc::bench
