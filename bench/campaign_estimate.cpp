#include "bench/campaign_estimate.hpp"

#include <chrono>

#include "runtime/core/rng.hpp"
#include "runtime/eval/evaluator.hpp"
#include "runtime/evo/gp/codec.hpp"
#include "runtime/evo/gp/init.hpp"

namespace esc::bench {

namespace {

// Per-core control steps per second of evaluating random genomes (an early generation:
// short epochs, many resets), measured for about `seconds`. Trees are drawn as a GP run's
// initial population is.
double measure_rate(const eval::ExperimentSpec& e, const control::ControllerSpec& c, double seconds) {
  eval::Evaluator evaluator(e);
  Rng rng(2024);
  std::vector<double> genome(c.genome_size());
  const evo::gp::GpSettings gp = e.gp.value_or(evo::gp::GpSettings{});
  std::int64_t steps = 0;
  const auto start = std::chrono::steady_clock::now();
  double elapsed = 0.0;
  for (std::uint64_t i = 0; elapsed < seconds || steps == 0; ++i) {
    if (c.is_tree())
      genome = evo::gp::encode(evo::gp::grow(*c.primitives, c.primitives->root(), gp.init_max_depth, rng));
    else
      for (double& g : genome) g = rng.uniform(e.es.lower, e.es.upper);
    steps += evaluator.evaluate(c, genome, i).steps;
    elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  return static_cast<double>(steps) / elapsed;
}

}  // namespace

std::vector<ControllerCost> estimate_campaign(const std::vector<eval::ExperimentSpec>& experiments,
                                              double seconds_each) {
  std::vector<ControllerCost> costs;
  for (const eval::ExperimentSpec& e : experiments) {
    for (const control::ControllerSpec& c : e.controllers) {
      ControllerCost k;
      k.experiment = e.name;
      k.controller = c.name;
      k.architecture = c.architecture();
      const bool evaluate_only = e.start_from && e.start_from->evaluate_only;
      const int per_generation = evaluate_only ? 1 : c.is_tree() && e.gp ? e.gp->population : e.es.lambda;
      k.evaluations = static_cast<double>(e.runs) * e.generations_for(c) * per_generation;
      k.max_steps = k.evaluations * e.epochs * e.steps;
      k.steps_per_second = measure_rate(e, c, seconds_each);
      costs.push_back(k);
    }
  }
  return costs;
}

}  // namespace esc::bench
