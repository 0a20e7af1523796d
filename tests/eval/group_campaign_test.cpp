// A group's campaign (docs/groups.md): four robots avoiding the walls and each other, each
// driven by its own copy of the evolved network. Bit-identical for any thread count, and its
// mean fitness improves (resumed after SIGKILL: tests/cli/results_test.cpp).
#include <gtest/gtest.h>

#include "runtime/eval/campaign.hpp"
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

}  // namespace
}  // namespace esc::eval
