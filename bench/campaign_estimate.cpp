#include "bench/campaign_estimate.hpp"

#include <algorithm>
#include <deque>
#include <functional>
#include <optional>
#include <span>

#include "bench/cpu_time.hpp"
#include "runtime/core/rng.hpp"
#include "runtime/eval/campaign.hpp"
#include "runtime/eval/evaluator.hpp"
#include "runtime/evo/es/es.hpp"
#include "runtime/genome/graph/graph_variation.hpp"
#include "runtime/genome/tree/codec.hpp"
#include "runtime/genome/tree/init.hpp"

namespace esc::bench {

namespace {

// Per-core control steps per second of evaluating random genomes (an early generation:
// short epochs, many resets), measured for about `seconds` of this thread's CPU time, which
// other work on the machine does not stretch. Trees are drawn as a GP run's initial
// population is, NEAT networks as NEAT's first population (its start, weights drawn anew).
double measure_rate(const eval::ExperimentSpec& e, const control::ControllerSpec& c, double seconds,
                    std::vector<double>& lengths) {
  eval::Evaluator evaluator(e);
  Rng rng(2024);
  std::vector<double> genome(e.genome_length(c));
  const evo::gp::GpSettings gp = e.tree_operators() != nullptr ? *e.tree_operators() : evo::gp::GpSettings{};
  const auto* given = e.settings_of<evo::EsSettings>(eval::ExperimentSpec::kDefaultNetworks);
  const evo::EsSettings es = given != nullptr ? *given : evo::EsSettings{};
  std::optional<genome::graph::GraphVariation> graphs;
  if (c.is_graph()) {
    const evo::Problem p = e.problem_of(c);
    graphs.emplace(p.graph.operators, p.graph);
  }
  std::int64_t steps = 0;
  const double start = thread_cpu_seconds();
  double elapsed = 0.0;
  for (std::uint64_t i = 0; elapsed < seconds || steps == 0; ++i) {
    if (c.is_tree())
      genome = genome::tree::encode(genome::tree::grow(*c.primitives, c.primitives->root(), gp.init_max_depth, rng));
    else if (graphs)
      genome = graphs->first(1, rng).front();
    else
      for (double& g : genome) g = rng.uniform(es.lower, es.upper);
    steps += evaluator.evaluate(c, genome, i).steps;
    const double before = elapsed;
    elapsed = thread_cpu_seconds() - start;
    lengths.push_back(elapsed - before);
  }
  return static_cast<double>(steps) / elapsed;
}

// A run waiting or advancing in the model, with the lengths its evaluations take in turn.
struct QueuedRun {
  std::span<const double> lengths;
  std::size_t evaluations;   // per generation
  int generations_left;
};

void schedule_rounds(std::deque<QueuedRun> queue, std::size_t workers, Schedule& out) {
  std::vector<QueuedRun> active;
  std::vector<double> busy_until(workers);
  std::size_t drawn = 0;
  while (true) {
    std::size_t pooled = 0;
    for (const QueuedRun& r : active) pooled += r.evaluations;
    while (!queue.empty() && eval::room_for_another_run(active.size(), pooled, workers, 0)) {
      pooled += queue.front().evaluations;
      active.push_back(queue.front());
      queue.pop_front();
    }
    if (active.empty()) return;
    // A min-heap of when each worker is next free: the first free takes the next evaluation.
    std::fill(busy_until.begin(), busy_until.end(), 0.0);
    for (const QueuedRun& r : active)
      for (std::size_t i = 0; i < r.evaluations; ++i) {
        const double length = r.lengths[drawn++ % r.lengths.size()];
        out.work_seconds += length;
        std::pop_heap(busy_until.begin(), busy_until.end(), std::greater<>());
        busy_until.back() += length;
        std::push_heap(busy_until.begin(), busy_until.end(), std::greater<>());
      }
    out.wall_seconds += *std::max_element(busy_until.begin(), busy_until.end());
    for (QueuedRun& r : active) --r.generations_left;
    std::erase_if(active, [](const QueuedRun& r) { return r.generations_left <= 0; });
  }
}

}  // namespace

Schedule schedule(const std::vector<eval::ExperimentSpec>& experiments, const std::vector<ControllerCost>& costs,
                  std::size_t workers, Lengths lengths) {
  Schedule out;
  std::vector<double> full(costs.size());
  std::size_t k = 0;
  for (const eval::ExperimentSpec& e : experiments) {
    std::deque<QueuedRun> queue;
    for (const control::ControllerSpec& c : e.controllers) {
      const ControllerCost& cost = costs.at(k);
      full[k] = static_cast<double>(e.epochs) * e.steps / cost.steps_per_second;
      const std::span<const double> drawn = lengths == Lengths::Measured && !cost.evaluation_seconds.empty()
                                                ? std::span<const double>(cost.evaluation_seconds)
                                                : std::span<const double>(&full[k], 1);
      for (int run = 0; run < e.runs; ++run)
        queue.push_back({drawn, e.evaluations_per_generation(c), e.generations_for(c)});
      ++k;
    }
    schedule_rounds(std::move(queue), std::max<std::size_t>(workers, 1), out);
  }
  return out;
}

std::vector<ControllerCost> estimate_campaign(const std::vector<eval::ExperimentSpec>& experiments,
                                              double seconds_each) {
  std::vector<ControllerCost> costs;
  for (const eval::ExperimentSpec& e : experiments) {
    for (const control::ControllerSpec& c : e.controllers) {
      ControllerCost k;
      k.experiment = e.name;
      k.controller = c.name;
      k.architecture = c.architecture();
      k.evaluations = static_cast<double>(e.runs) * e.generations_for(c) *
                      static_cast<double>(e.evaluations_per_generation(c));
      k.max_steps = k.evaluations * e.epochs * e.steps;
      k.steps_per_second = measure_rate(e, c, seconds_each, k.evaluation_seconds);
      costs.push_back(k);
    }
  }
  return costs;
}

}  // namespace esc::bench
