// A group's campaign (docs/groups.md): four robots avoiding the walls and each other, each
// driven by its own copy of the evolved network. Bit-identical for any thread count, and its
// mean fitness improves (resumed after SIGKILL: tests/cli/results_test.cpp).
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "runtime/core/rng.hpp"
#include "runtime/eval/campaign.hpp"
#include "runtime/eval/evaluator.hpp"
#include "tests/eval/campaign_checks.hpp"
#include "tests/eval/test_experiment.hpp"

namespace esc::eval {
namespace {

struct Quiet final : CampaignListener {};

ExperimentSpec group_experiment() {
  ExperimentSpec spec = testing::small_experiment();
  spec.arena.width_m = 0.8;
  spec.arena.height_m = 0.6;
  spec.robots = 4;
  spec.generations = 10;
  return spec;
}

TEST(GroupCampaign, BitIdenticalForAnyThreadCount) {
  const ExperimentSpec spec = group_experiment();
  Quiet quiet;
  const CampaignResult one = run_campaign(spec, {1}, quiet);
  const CampaignResult two = run_campaign(spec, {2}, quiet);
  const auto& a = one.controllers.front().runs;
  const auto& b = two.controllers.front().runs;
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t r = 0; r < a.size(); ++r) {
    EXPECT_EQ(a[r].best_genome, b[r].best_genome);
    ASSERT_EQ(a[r].generations.size(), b[r].generations.size());
    for (std::size_t g = 0; g < a[r].generations.size(); ++g) {
      EXPECT_EQ(a[r].generations[g].mean, b[r].generations[g].mean);
      EXPECT_EQ(a[r].generations[g].steps, b[r].generations[g].steps);
    }
  }
}

TEST(GroupCampaign, MeanFitnessImproves) {
  const ExperimentSpec spec = group_experiment();
  Quiet quiet;
  const auto [first, last] = testing::first_and_last_mean(run_campaign(spec, {2}, quiet));
  EXPECT_GT(last, first * 1.2) << "mean fitness " << first << " -> " << last;
}

struct Collect final : TraceSink {
  std::vector<TraceStep> steps;
  void on_step(const TraceStep& t) override { steps.push_back(t); }
};

// A group's replay (docs/groups.md): a row per robot per step, in robot order, the same
// evaluation as untraced, each row's group observables those of the rows' positions, and the
// last row's fitness the evaluation's.
TEST(GroupCampaign, ATracedEvaluationHoldsEveryRobotAndItsGroupObservables) {
  const ExperimentSpec spec = group_experiment();
  const control::ControllerSpec& c = spec.controllers.front();
  Rng rng(3);
  std::vector<double> genome(c.genome_size());
  for (double& g : genome) g = rng.uniform(-1.0, 1.0);
  Evaluator evaluator(spec);
  const Evaluation plain = evaluator.evaluate(c, genome, 11);
  Collect trace;
  const Evaluation traced = evaluator.evaluate(c, genome, 11, &trace);
  EXPECT_EQ(plain.fitness, traced.fitness);
  EXPECT_EQ(plain.steps, traced.steps);
  ASSERT_EQ(trace.steps.size(), static_cast<std::size_t>(plain.steps) * 4);
  EXPECT_EQ(trace_robots(trace.steps), 4U);
  EXPECT_EQ(trace.steps.back().fitness, plain.fitness);
  for (std::size_t at = 0; at < trace.steps.size(); at += 4) {
    double cx = 0.0, cy = 0.0;
    for (std::size_t r = 0; r < 4; ++r) {
      const TraceStep& t = trace.steps[at + r];
      ASSERT_TRUE(t.grouped);
      ASSERT_EQ(t.robot, static_cast<int>(r));
      ASSERT_EQ(t.step, trace.steps[at].step);
      cx += t.pose.x_m;
      cy += t.pose.y_m;
    }
    cx /= 4.0;
    cy /= 4.0;
    double spread = 0.0, pairs = 0.0;
    for (std::size_t r = 0; r < 4; ++r) {
      const TraceStep& t = trace.steps[at + r];
      double nearest = 1e9;
      for (std::size_t q = 0; q < 4; ++q) {
        if (q == r) continue;
        const TraceStep& u = trace.steps[at + q];
        const double d = std::hypot(t.pose.x_m - u.pose.x_m, t.pose.y_m - u.pose.y_m);
        nearest = std::min(nearest, d);
        if (q > r) pairs += d;
      }
      const double to_centroid = std::hypot(t.pose.x_m - cx, t.pose.y_m - cy);
      spread = std::max(spread, to_centroid);
      EXPECT_NEAR(t.group[0], cx, 1e-12);
      EXPECT_NEAR(t.group[1], cy, 1e-12);
      EXPECT_NEAR(t.group[3], to_centroid, 1e-12);
      EXPECT_NEAR(t.group[4], nearest, 1e-12);
    }
    for (std::size_t r = 0; r < 4; ++r) {
      EXPECT_NEAR(trace.steps[at + r].group[5], pairs / 6.0, 1e-12);
      EXPECT_NEAR(trace.steps[at + r].group[6], spread, 1e-12);
    }
  }
}

// A stored replay keeps whole epochs, else whole steps of the first epoch (every robot).
TEST(GroupCampaign, AStoredReplayIsCutAtWholeEpochsOrWholeSteps) {
  std::vector<TraceStep> rows;
  for (int e = 0; e < 3; ++e)
    for (int s = 0; s < 10; ++s)
      for (int r = 0; r < 3; ++r) {
        TraceStep t;
        t.epoch = e;
        t.step = s;
        t.robot = r;
        t.grouped = true;
        rows.push_back(t);
      }
  EXPECT_EQ(trace_rows_kept(rows, 90), 90U);
  EXPECT_EQ(trace_rows_kept(rows, 89), 60U);   // two whole epochs
  EXPECT_EQ(trace_rows_kept(rows, 31), 30U);   // the first epoch
  EXPECT_EQ(trace_rows_kept(rows, 29), 27U);   // its first nine steps, every robot
  EXPECT_EQ(trace_rows_kept(rows, 2), 0U);     // less than a step: none
}

}  // namespace
}  // namespace esc::eval
