// Resume and replay in the campaign layer: continuing a run from a RunState taken after any
// generation reproduces the uninterrupted run bit for bit; a traced evaluation is the same
// evaluation as an untraced one; a run's best evaluation replays to its best fitness.
#include <gtest/gtest.h>

#include "runtime/eval/campaign.hpp"
#include "tests/eval/campaign_checks.hpp"
#include "tests/eval/test_experiment.hpp"
#include "tests/algorithm_settings.hpp"

namespace esc::eval {
namespace {

using testing::Snapshotter;

TEST(Resume, ContinuingFromAnyGenerationIsBitIdentical) {
  ExperimentSpec spec = testing::small_experiment();
  spec.generations = 5;
  CampaignListener quiet;
  const CampaignResult whole = run_campaign(spec, {2}, quiet);
  // 4: the last generation is done, the run is not yet closed.
  testing::expect_resumes_to(spec, whole, {0, 2, 4});
}

TEST(Resume, BestEvaluationReplaysToTheBestFitness) {
  const ExperimentSpec spec = testing::small_experiment();
  Snapshotter snap;
  const CampaignResult res = run_campaign(spec, {2, nullptr, true}, snap);
  ASSERT_EQ(snap.traces.size(), static_cast<std::size_t>(spec.runs));
  for (const auto& [run, trace] : snap.traces) {
    ASSERT_FALSE(trace.empty());
    EXPECT_EQ(trace.back().fitness, run.best_fitness);
    EXPECT_EQ(trace.front().epoch, 0);
    EXPECT_EQ(trace.back().epoch, spec.epochs - 1);
    EXPECT_EQ(run.best_fitness, res.controllers[0].runs[static_cast<std::size_t>(run.run)].best_fitness);
    for (const TraceStep& t : trace) {
      EXPECT_EQ(t.action, -1);   // classical head
      EXPECT_GE(t.pose.x_m, 0.0);
      EXPECT_LE(t.pose.x_m, spec.arena.width_m);
    }
  }
}

TEST(Resume, TracingDoesNotChangeTheEvaluation) {
  const ExperimentSpec spec = testing::small_experiment();
  const std::vector<double> genome(spec.controllers[0].genome_size(), 0.3);
  struct Count final : TraceSink {
    std::int64_t steps = 0;
    void on_step(const TraceStep&) override { ++steps; }
  } count;
  Evaluator a(spec);
  Evaluator b(spec);
  const Evaluation plain = a.evaluate(spec.controllers[0], genome, 99);
  const Evaluation traced = b.evaluate(spec.controllers[0], genome, 99, &count);
  EXPECT_EQ(plain.fitness, traced.fitness);
  EXPECT_EQ(plain.steps, traced.steps);
  EXPECT_EQ(count.steps, plain.steps);
}

}  // namespace
}  // namespace esc::eval
