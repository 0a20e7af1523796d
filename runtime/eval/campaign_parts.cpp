#include "runtime/eval/campaign_parts.hpp"

#include <algorithm>
#include <cmath>


namespace esc::eval::detail {

namespace {

// Collects a traced evaluation and counts the steps each action acted on.
struct Recorder final : TraceSink {
  std::vector<TraceStep> steps;
  std::vector<std::int64_t> usage;
  void on_step(const TraceStep& t) override {
    steps.push_back(t);
    if (t.action >= 0 && static_cast<std::size_t>(t.action) < usage.size()) ++usage[static_cast<std::size_t>(t.action)];
  }
};

}  // namespace

std::optional<std::size_t> RunJob::record(std::span<const double> fitness, const GenerationStats& stats) {
  state_.generations.push_back(stats);
  return improve_best(state_, stats.generation, fitness);
}

GenerationStats summarise(int generation, std::span<const double> fitness, std::int64_t steps, double seconds) {
  GenerationStats g;
  g.generation = generation;
  g.evaluations = static_cast<std::int64_t>(fitness.size());
  g.steps = steps;
  g.seconds = seconds;
  double sum = 0.0;
  g.best = fitness.front();
  for (const double f : fitness) {
    sum += f;
    g.best = std::max(g.best, f);
  }
  const auto n = static_cast<double>(fitness.size());
  g.mean = sum / n;
  double sq = 0.0;
  for (const double f : fitness) sq += (f - g.mean) * (f - g.mean);
  g.sd = fitness.size() > 1 ? std::sqrt(sq / (n - 1.0)) : 0.0;
  return g;
}

std::optional<std::size_t> improve_best(RunState& st, int generation, std::span<const double> fitness) {
  std::optional<std::size_t> found;
  for (std::size_t i = 0; i < fitness.size(); ++i) {
    if (!st.has_best || fitness[i] > st.best_fitness) {
      st.has_best = true;
      st.best_fitness = fitness[i];
      st.best_generation = generation;
      st.best_index = static_cast<int>(i);
      found = i;
    }
  }
  return found;
}

RunResult close_run(RunState&& st) {
  RunResult result;
  result.run = st.run;
  result.seed = st.seed;
  result.generations = std::move(st.generations);
  result.best_fitness = st.best_fitness;
  result.best_genome = std::move(st.best_genome);
  result.best_generation = st.best_generation;
  result.best_index = st.best_index;
  return result;
}

void replay_best(const ExperimentSpec& spec, const control::ControllerSpec& controller, RunResult& result,
                 const CampaignOptions& options, Evaluators& ev, CampaignListener& listener,
                 const std::function<Evaluation(Evaluator&, std::uint64_t, TraceSink*)>& replay) {
  Recorder rec;
  rec.usage.assign(controller.choice_names().size(), 0);
  if (options.trace_best)
    rec.steps.reserve(static_cast<std::size_t>(spec.epochs) * static_cast<std::size_t>(spec.steps));
  if (!options.trace_best && rec.usage.empty()) return;
  const std::uint64_t seed =
      evaluation_seed(result.seed, result.best_generation, static_cast<std::size_t>(result.best_index));
  (void)replay(ev.workers.local(), seed, &rec);
  result.action_usage = std::move(rec.usage);
  if (options.trace_best) listener.best_traced(controller, result, rec.steps);
}

}  // namespace esc::eval::detail
