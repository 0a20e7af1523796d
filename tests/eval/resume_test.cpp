// Resume and replay in the campaign layer: continuing a run from a RunState taken after any
// generation reproduces the uninterrupted run bit for bit; a traced evaluation is the same
// evaluation as an untraced one; a run's best evaluation replays to its best fitness.
#include <gtest/gtest.h>

#include "runtime/eval/campaign.hpp"
#include "tests/eval/test_experiment.hpp"

namespace esc::eval {
namespace {

// Keeps the state after generation `at` of every run.
struct Snapshotter final : CampaignListener {
  int at = 0;
  std::vector<ResumePoint::InProgress> states;
  std::vector<std::pair<RunResult, std::vector<TraceStep>>> traces;
  void checkpoint(const control::ControllerSpec& c, const RunState& s) override {
    if (static_cast<int>(s.generations.size()) == at + 1) states.push_back({c.name, s});
  }
  void best_traced(const control::ControllerSpec&, const RunResult& r, std::span<const TraceStep> t) override {
    traces.emplace_back(r, std::vector<TraceStep>(t.begin(), t.end()));
  }
};

void expect_same(const CampaignResult& a, const CampaignResult& b) {
  ASSERT_EQ(a.controllers.size(), b.controllers.size());
  for (std::size_t c = 0; c < a.controllers.size(); ++c) {
    ASSERT_EQ(a.controllers[c].runs.size(), b.controllers[c].runs.size());
    for (std::size_t r = 0; r < a.controllers[c].runs.size(); ++r) {
      const RunResult& x = a.controllers[c].runs[r];
      const RunResult& y = b.controllers[c].runs[r];
      EXPECT_EQ(x.best_fitness, y.best_fitness);
      EXPECT_EQ(x.best_genome, y.best_genome);
      EXPECT_EQ(x.best_generation, y.best_generation);
      EXPECT_EQ(x.best_index, y.best_index);
      ASSERT_EQ(x.generations.size(), y.generations.size());
      for (std::size_t g = 0; g < x.generations.size(); ++g) {
        EXPECT_EQ(x.generations[g].best, y.generations[g].best);
        EXPECT_EQ(x.generations[g].mean, y.generations[g].mean);
        EXPECT_EQ(x.generations[g].sd, y.generations[g].sd);
        EXPECT_EQ(x.generations[g].steps, y.generations[g].steps);
      }
    }
  }
}

TEST(Resume, ContinuingFromAnyGenerationIsBitIdentical) {
  ExperimentSpec spec = testing::small_experiment();
  spec.es.generations = 5;
  CampaignListener quiet;
  const CampaignResult whole = run_campaign(spec, {2}, quiet);
  for (int at : {0, 2, 4}) {   // 4: the last generation is done, the run is not yet closed
    Snapshotter snap;
    snap.at = at;
    (void)run_campaign(spec, {1}, snap);
    ASSERT_EQ(snap.states.size(), static_cast<std::size_t>(spec.runs));
    // Run 0 finished (taken from the uninterrupted result), run 1 in progress.
    ResumePoint point;
    point.finished.push_back({spec.controllers[0].name, whole.controllers[0].runs[0]});
    point.in_progress.push_back(snap.states[1]);
    CampaignListener none;
    const CampaignResult resumed = run_campaign(spec, {2, &point}, none);
    expect_same(whole, resumed);
  }
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
