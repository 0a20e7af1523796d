#include "runtime/eval/campaign_parts.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "runtime/eval/moments.hpp"
#include "runtime/expr/program.hpp"


namespace esc::eval::detail {

namespace {

// Collects a traced evaluation (a group's, its first kMaxReplayRows rows and one more, which
// trace_rows_kept then cuts) and counts the steps each action acted on.
struct Recorder final : TraceSink {
  std::vector<TraceStep> steps;
  std::vector<std::int64_t> usage;
  std::size_t most = std::numeric_limits<std::size_t>::max();
  void on_step(const TraceStep& t) override {
    if (steps.size() < most) steps.push_back(t);
    if (t.action >= 0 && static_cast<std::size_t>(t.action) < usage.size()) ++usage[static_cast<std::size_t>(t.action)];
  }
};

}  // namespace

const StartFrom::Origin* start_of(const ExperimentSpec& spec, const control::ControllerSpec& controller,
                                  int run) noexcept {
  if (!spec.start_from) return nullptr;
  return spec.start_from->origin(static_cast<std::size_t>(&controller - spec.controllers.data()), run);
}

RunState fresh_run(const ExperimentSpec& spec, int run, const StartFrom::Origin* start) {
  RunState st;
  st.run = run;
  st.seed = run_seed(spec.seed, run);
  if (start != nullptr)
    st.transfer = Transfer{spec.start_from->experiment, start->run, start->fitness, spec.evaluates_only(), std::nullopt};
  return st;
}

GenerationStats summarise(int generation, std::span<const double> fitness, std::int64_t steps, double seconds) {
  GenerationStats g;
  g.generation = generation;
  g.evaluations = static_cast<std::int64_t>(fitness.size());
  g.steps = steps;
  g.seconds = seconds;
  g.best = fitness.front();
  for (const double f : fitness) {
    g.best = std::max(g.best, f);
    if (std::abs(f) >= expr::kSaturation) ++g.saturated;
  }
  const Moments m = moments(fitness);
  g.mean = m.mean;
  g.sd = m.sd;
  return g;
}

ResultColumns result_columns(const ExperimentSpec& spec, std::size_t most_choices) noexcept {
  ResultColumns c;
  c.objectives = kResultUsage + most_choices;
  c.descriptors = c.objectives + spec.further.size();
  c.width = c.descriptors + spec.descriptors.size();
  return c;
}

void write_result(const Evaluation& e, const ResultColumns& columns, double* row) noexcept {
  row[kResultFitness] = e.fitness;
  row[kResultSteps] = static_cast<double>(e.steps);
  for (std::size_t c = 0; c < e.usage.size() && kResultUsage + c < columns.objectives; ++c)
    row[kResultUsage + c] = static_cast<double>(e.usage[c]);
  std::copy(e.objectives.begin(), e.objectives.end(), row + columns.objectives);
  std::copy(e.descriptors.begin(), e.descriptors.end(), row + columns.descriptors);
}

std::vector<evo::Outcome> outcomes_of(const ExperimentSpec& spec, std::span<const double> rows,
                                      const ResultColumns& columns) {
  std::vector<evo::Outcome> out(rows.size() / columns.width);
  for (std::size_t i = 0; i < out.size(); ++i) {
    const double* row = rows.data() + i * columns.width;
    evo::Outcome& o = out[i];
    o.objectives.reserve(1 + spec.further.size());
    o.objectives.push_back(row[kResultFitness]);
    for (std::size_t k = 0; k < spec.further.size(); ++k) {
      o.objectives.push_back(spec.as_declared(k + 1, row[columns.objectives + k]));
    }
    o.descriptors.assign(row + columns.descriptors, row + columns.width);
  }
  return out;
}

GenerationUsage summarise_usage(std::span<const double> rows, std::size_t width, std::size_t choices) {
  GenerationUsage u;
  const std::size_t n = width == 0 ? 0 : rows.size() / width;
  if (choices == 0 || n == 0 || kResultUsage + choices > width) return u;
  // The generation's best evaluation: the first of the best fitness, as improve_best picks.
  std::size_t best = 0;
  for (std::size_t i = 1; i < n; ++i)
    if (rows[i * width + kResultFitness] > rows[best * width + kResultFitness]) best = i;
  u.steps_total = static_cast<std::int64_t>(rows[best * width + kResultSteps]);
  u.best.resize(choices);
  u.mean.assign(choices, 0.0);
  for (std::size_t c = 0; c < choices; ++c) {
    u.best[c] = static_cast<std::int64_t>(rows[best * width + kResultUsage + c]);
    double sum = 0.0;
    for (std::size_t i = 0; i < n; ++i) sum += rows[i * width + kResultUsage + c];
    u.mean[c] = sum / static_cast<double>(n);
  }
  return u;
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
  result.transfer = std::move(st.transfer);
  result.success_evaluation = st.success_evaluation;
  return result;
}

void replay_best(const ExperimentSpec& spec, const control::ControllerSpec& controller, RunResult& result,
                 const CampaignOptions& options, Evaluators& ev, CampaignListener& listener,
                 const std::function<Evaluation(Evaluator&, std::uint64_t, TraceSink*)>& replay) {
  const std::uint64_t seed =
      evaluation_seed(result.seed, result.best_generation, static_cast<std::size_t>(result.best_index));
  // A group's usage is a robot's share (the evaluation's): its replay is traced only when asked.
  if (spec.robots > 1) {
    if (!options.trace_best && controller.choice_names().empty()) return;
    Recorder rec;
    rec.most = kMaxReplayRows + 1;
    if (options.trace_best) rec.steps.reserve(replay_rows(spec) + 1);
    const Evaluation e = replay(ev.workers.local(), seed, options.trace_best ? &rec : nullptr);
    result.action_usage.assign(e.usage.begin(), e.usage.end());
    if (options.trace_best)
      listener.best_traced(controller, result, std::span(rec.steps).first(trace_rows_kept(rec.steps, kMaxReplayRows)));
    return;
  }
  Recorder rec;
  rec.usage.assign(controller.choice_names().size(), 0);
  if (options.trace_best) rec.steps.reserve(replay_rows(spec));
  if (!options.trace_best && rec.usage.empty()) return;
  (void)replay(ev.workers.local(), seed, &rec);
  result.action_usage = std::move(rec.usage);
  if (options.trace_best) listener.best_traced(controller, result, rec.steps);
}

}  // namespace esc::eval::detail
