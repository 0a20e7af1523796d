// The campaign-estimate schedule (bench/campaign_estimate.hpp) against hand-counted rounds:
// runs advance together as run_campaign lets them, a round lasts as long as its busiest
// worker, and measured lengths are drawn in turn.
#include "bench/campaign_estimate.hpp"

#include <gtest/gtest.h>

#include "tests/eval/test_experiment.hpp"

namespace esc::bench {
namespace {

// small_experiment: 2 runs x 6 generations x 20 offspring of 3 epochs x 60 steps; at 180
// steps/s a full-length evaluation takes 1 s.
std::vector<ControllerCost> one_second_each() {
  ControllerCost c;
  c.steps_per_second = 180.0;
  return {c};
}

TEST(Schedule, OneWorkerDoesEverythingInTurn) {
  const std::vector<eval::ExperimentSpec> e{testing::small_experiment()};
  const Schedule s = schedule(e, one_second_each(), 1, Lengths::Full);
  EXPECT_DOUBLE_EQ(s.work_seconds, 240.0);
  EXPECT_DOUBLE_EQ(s.wall_seconds, 240.0);
  EXPECT_DOUBLE_EQ(s.efficiency(1), 1.0);
}

TEST(Schedule, RunsAdvanceTogetherAndRoundsWaitForTheirLastEvaluation) {
  const std::vector<eval::ExperimentSpec> e{testing::small_experiment()};
  // 7 workers: both runs join (20 < 16 x 7); a round pools 40 evaluations: 6 waves of 1 s.
  EXPECT_DOUBLE_EQ(schedule(e, one_second_each(), 7, Lengths::Full).wall_seconds, 6 * 6.0);
  // 16 workers: 40 evaluations take 3 waves, the last one half idle.
  const Schedule s = schedule(e, one_second_each(), 16, Lengths::Full);
  EXPECT_DOUBLE_EQ(s.wall_seconds, 6 * 3.0);
  EXPECT_DOUBLE_EQ(s.efficiency(16), 240.0 / (16 * 18.0));
}

TEST(Schedule, MeasuredLengthsAreDrawnInTurn) {
  const std::vector<eval::ExperimentSpec> e{testing::small_experiment()};
  std::vector<ControllerCost> costs = one_second_each();
  costs[0].evaluation_seconds = {1.0, 3.0};
  const Schedule alone = schedule(e, costs, 1, Lengths::Measured);
  EXPECT_DOUBLE_EQ(alone.work_seconds, 120 * 1.0 + 120 * 3.0);
  EXPECT_DOUBLE_EQ(alone.wall_seconds, alone.work_seconds);
  // 40 workers take a round's 40 evaluations at once: each round lasts its longest, 3 s.
  const Schedule wide = schedule(e, costs, 40, Lengths::Measured);
  EXPECT_DOUBLE_EQ(wide.wall_seconds, 6 * 3.0);
  EXPECT_DOUBLE_EQ(schedule(e, costs, 40, Lengths::Full).wall_seconds, 6 * 1.0);
}

}  // namespace
}  // namespace esc::bench
