// A generation's behavior usage from its pooled evaluation results (fitness, steps, then the
// steps of each choice; rows wider than a controller's choices when another controller of
// the round has more): the best evaluation's counts (the first of the best fitness, as
// improve_best picks it), their mean over the evaluations, and the best evaluation's steps.
#include <gtest/gtest.h>

#include "runtime/eval/campaign_parts.hpp"

namespace esc::eval::detail {
namespace {

TEST(GenerationUsage, TheFirstBestEvaluationsCountsAndTheMean) {
  // Width 5: fitness, steps, 2 choices of this controller and one column it does not use.
  const std::vector<double> rows = {
      3.0, 100, 60, 40, 0,   //
      7.5, 90,  10, 80, 0,   // the best
      7.5, 120, 100, 20, 0,  // as good, later: not it
      -1.0, 30, 30, 0, 0,
  };
  const GenerationUsage u = summarise_usage(rows, 5, 2);
  EXPECT_EQ(u.steps_total, 90);
  EXPECT_EQ(u.best, (std::vector<std::int64_t>{10, 80}));
  EXPECT_EQ(u.mean, (std::vector<double>{(60.0 + 10 + 100 + 30) / 4, (40.0 + 80 + 20 + 0) / 4}));
  RunState st;
  const std::vector<double> fitness = {3.0, 7.5, 7.5, -1.0};
  EXPECT_EQ(improve_best(st, 0, fitness), std::optional<std::size_t>(1));   // the same individual
}

TEST(GenerationUsage, NoneForAControllerWithoutChoices) {
  const std::vector<double> rows = {1.0, 50, 2.0, 60};
  EXPECT_TRUE(summarise_usage(rows, 2, 0).empty());
  EXPECT_TRUE(summarise_usage({}, 4, 2).empty());
}

}  // namespace
}  // namespace esc::eval::detail
