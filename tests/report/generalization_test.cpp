// The generalization figures of runs carried into a new setting (runtime/report/generalization.hpp).
#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include <gtest/gtest.h>

#include "runtime/report/generalization.hpp"

namespace esc::report {
namespace {

// A run started from a genome that scored `origin` there and `here` here, whose generations'
// best fitnesses are `best`.
eval::RunResult carried(int run, double origin, double here, std::vector<double> best, bool evaluate_only = false) {
  eval::RunResult r;
  r.run = run;
  for (double b : best) r.generations.push_back(eval::GenerationStats{.best = b});
  r.best_fitness = *std::max_element(best.begin(), best.end());
  r.transfer = eval::Transfer{"energy", run, origin, evaluate_only, here};
  return r;
}

TEST(Transfers, LossMadeUpIsTheShareOfTheDropRecovered) {
  // Lost 20, got 10 back (half, the paper's "only recover half of it"); lost 40, got it all
  // back and 20 more (150%); lost nothing (no share).
  const std::vector<eval::RunResult> runs{carried(0, 100.0, 80.0, {80.0, 85.0, 90.0}),
                                          carried(1, 100.0, 60.0, {60.0, 100.0, 120.0}),
                                          carried(2, 100.0, 105.0, {105.0, 101.0})};
  const auto s = summarise_transfers(runs);
  ASSERT_TRUE(s.has_value());
  ASSERT_EQ(s->runs.size(), 3u);
  ASSERT_TRUE(s->runs[0].loss_regained.has_value() && s->runs[1].loss_regained.has_value());
  EXPECT_DOUBLE_EQ(*s->runs[0].loss_regained, 50.0);
  EXPECT_DOUBLE_EQ(*s->runs[1].loss_regained, 150.0);
  EXPECT_FALSE(s->runs[2].loss_regained.has_value());
  ASSERT_TRUE(s->runs[0].best_here.has_value() && s->runs[2].best_here.has_value());
  EXPECT_DOUBLE_EQ(*s->runs[0].best_here, 90.0);
  EXPECT_DOUBLE_EQ(*s->runs[2].best_here, 105.0);
  // Pooled over the two runs that lost something: (10 + 60) / (20 + 40).
  EXPECT_DOUBLE_EQ(s->loss_regained_pooled, 100.0 * 70.0 / 60.0);
  EXPECT_DOUBLE_EQ(s->best_here_mean, (90.0 + 120.0 + 105.0) / 3);
  EXPECT_EQ(s->regained, 2u);                        // runs 1 (generation 1) and 2 (generation 0)
  EXPECT_DOUBLE_EQ(s->regained_median, 0.5);
  EXPECT_DOUBLE_EQ(s->change_mean, (-20.0 - 40.0 + 5.0) / 3);
}

TEST(Transfers, AnEvaluatedGenomeHasNoBestHereNorLossMadeUp) {
  const std::vector<eval::RunResult> runs{carried(0, 100.0, 80.0, {80.0}, true)};
  const auto s = summarise_transfers(runs);
  ASSERT_TRUE(s.has_value());
  EXPECT_TRUE(s->evaluate_only);
  EXPECT_FALSE(s->runs[0].best_here.has_value());
  EXPECT_FALSE(s->runs[0].loss_regained.has_value());
  EXPECT_FALSE(s->runs[0].regained_at.has_value());
  EXPECT_TRUE(std::isnan(s->loss_regained_pooled));
  EXPECT_TRUE(std::isnan(s->best_here_mean));
  ASSERT_TRUE(s->runs[0].change_percent.has_value());
  EXPECT_DOUBLE_EQ(*s->runs[0].change_percent, -20.0);
}

TEST(Transfers, NoTransferNoSummary) {
  eval::RunResult plain;
  plain.generations.push_back(eval::GenerationStats{.best = 1.0});
  EXPECT_FALSE(summarise_transfers({plain}).has_value());
}

}  // namespace
}  // namespace esc::report
